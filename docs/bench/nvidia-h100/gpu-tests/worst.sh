#!/usr/bin/env bash
# The largest single-pixel errors of the defaults in the H100 accuracy record (ToyCar's camera 1:
# 43 pixels, up to 69/255; boxes: one pixel at 15/255), drawn again with --diff, with and without
# the glass; and bench's SM clock read during the timed frames at four million lights (3840x2160,
# compute raster), where the reading after glFinish caught the idle clock. Carry .devbin.txz, .gl
# and .corpus-kh. Everything lands in $OUT/worst.tgz.
set -u
FINAL=$OUT
OUT=/tmp/results/worst
mkdir -p $OUT
[ -d .devbin ] || tar xJf .devbin.txz
[ -d .corpus-kh/corpus ] || (cd .corpus-kh && tar xJf khronos.txz)
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
M="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
pack() { tar czf $FINAL/worst.tgz -C /tmp/results worst; }
frame() {  # name, scene and camera flags
  name=$1; shift
  for glass in on off; do
    C="$* --size 2560x1440 --lights 4096 --frames 0 --backend egl --brdf ggx --transparency $glass"
    $M render $C --method naive --out /tmp/n.png > /dev/null 2>&1
    for method in deferred visibility; do
      $M render $C --method $method --out /tmp/m.png > /dev/null 2>&1
      echo "$name glass $glass $method: $($M compare /tmp/m.png /tmp/n.png --diff $OUT/$name-$glass-$method.png --crop 256x144 2>&1)" >> $OUT/worst.txt
    done
  done
}
frame ToyCar-gltf1 --scene .corpus-kh/corpus/khronos/ToyCar/glTF/ToyCar.gltf --camera gltf:1
frame boxes --scene boxes
pack
B="$M bench --backend egl --warmup 5 --timed-frames 30 --method visibility --camera atrium-set --light-radius overlap:32"
$B --lights 4194304 --size 3840x2160 --vis-raster compute --out $OUT --name clock-4m > $OUT/clock-4m.log 2>&1
pack
