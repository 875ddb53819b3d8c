#!/usr/bin/env bash
# Forward+ against naive with --msaa at the glass's edges, on the H100 (nvidia-h100-x1), and
# pixelRayView's rewrite (354864a) checked byte for byte against main before it (6feb8fe).
# Carry .gl, .devbin.txz (main: manylights and its libraries) and .devbin-old.txz (6feb8fe's
# manylights alone, run with .devbin's libraries). Results in $OUT.
set -u
for b in .devbin .devbin-old; do [ -d $b ] || tar xJf $b.txz; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
NEW=.devbin/manylights OLD=.devbin-old/manylights
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
{
for case in "1280x720 4096 4" "1280x720 1024 4" "2560x1440 4096 4" "1280x720 4096 8"; do
  set -- $case
  for m in naive forward-plus; do
    $NEW render --scene atrium --size $1 --lights $2 --msaa $3 --method $m --backend egl \
      --out $OUT/msaa-$1-$2-$3-$m.png > /dev/null
  done
  echo "msaa $3, $1, $2 lights: $($NEW compare $OUT/msaa-$1-$2-$3-naive.png $OUT/msaa-$1-$2-$3-forward-plus.png)"
done
for cam in default -15,1.7,-6.3,15,1.7,-6.3,60 0,28,0.5,0,0,0,60 -16,3,-4.5,16,1.5,4.5,60; do
  c=$([ $cam = default ] || echo "--camera $cam")
  for m in "visibility" "visibility --vis-raster compute" "deferred" "deferred --gbuffer standard" "forward-plus" "naive"; do
    for b in OLD NEW; do
      ${!b} render --scene atrium $c --size 2560x1440 --lights 4096 --method $m --backend egl \
        --out-float /tmp/$b.pfm --out /tmp/$b.png > /dev/null
    done
    cmp -s /tmp/OLD.pfm /tmp/NEW.pfm && r=identical || r="DIFFER: $($NEW compare /tmp/OLD.png /tmp/NEW.png)"
    echo "pixelRayView, atrium $cam, $m: $r"
  done
done
} > $OUT/results.txt 2>&1
