#!/usr/bin/env bash
# Issue 30's compute raster on the H100, one binary, one command: the visibility buffer by the
# hardware raster and by the compute raster, (1) timed on the atrium as it ships (glass on), GGX,
# 2560x1440, overlap:32, exact lists, atrium-set, median of 30 frames after 5, at 65,536 and
# 1,048,576 lights; (2) each against naive on the atrium, the AMD scenes and two glossy files.
set -u
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
M="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
D=docs/bench/nvidia-h100/compute-raster
S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl --method visibility --vis-raster hardware,compute'
$M bench $S --lights 65536 --out $OUT --name raster-64k > $OUT/raster-64k.log 2>&1
$M bench $S --lights 1048576 --out $OUT --name raster-1m > $OUT/raster-1m.log 2>&1
$M bench --sweep $D/accuracy.sweep.json --backend egl --out $OUT --name accuracy > $OUT/accuracy.log 2>&1
# (3) The two rasters' frames against each other (a different id shows as a different pixel).
mkdir -p /tmp/frames
for scene in atrium .corpus-d/amd/sponza/Sponza.gltf; do
  for r in hardware compute; do
    $M render --scene $scene --method visibility --vis-raster $r --lights 4096 --size 2560x1440 --backend egl --out /tmp/frames/$r.png > /dev/null 2>&1
  done
  echo "$scene: $($M compare /tmp/frames/compute.png /tmp/frames/hardware.png 2>&1)" >> $OUT/frames.txt
done
kill %1
