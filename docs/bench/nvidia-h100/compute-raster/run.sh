#!/usr/bin/env bash
# Issue 30's compute raster on the H100 (nvidia-h100-x1), one binary (.devbin, tools/pack-for-gpu),
# one command: (1) the visibility buffer by the hardware and by the compute raster, timed per
# pass (timing.sweep.json); (2) each against naive (accuracy.sweep.json); (3) where the compute
# raster's triangles went (render --stats); (4) its ids against the hardware raster's (the GPU
# and corpus tests' ComputeRaster cases, run on the H100; the corpus copy is .corpus-d, linked
# where the test binaries look). Carry .devbin, .gl and .corpus-d (Sponza, NormalTangentMirrorTest).
set -u
D=docs/bench/nvidia-h100/compute-raster
M="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> /tmp/smclock.csv; sleep 1; done) &
$M bench --sweep $D/timing.sweep.json --backend egl --out $OUT --name timing > /tmp/timing.log 2>&1
$M bench --sweep $D/accuracy.sweep.json --backend egl --out $OUT --name accuracy > /tmp/accuracy.log 2>&1
for c in default -15,1.7,-6.3,15,1.7,-6.3,60 0,28,0.5,0,0,0,60 -16,3,-4.5,16,1.5,4.5,60; do
  echo "atrium $c: $($M render --camera $c --method visibility --vis-raster compute --lights 65536 --size 2560x1440 --backend egl --stats --overwrite --out /tmp/a.png 2>&1 | grep 'compute raster')" >> $OUT/work.txt
done
for c in 0 1 2 3; do
  echo "sponza gltf:$c: $($M render --scene .corpus-d/amd/sponza/Sponza.gltf --camera gltf:$c --method visibility --vis-raster compute --lights 4096 --size 2560x1440 --backend egl --stats --overwrite --out /tmp/a.png 2>&1 | grep 'compute raster')" >> $OUT/work.txt
done
xz -dk .devbin/ml_gpu_tests.xz .devbin/ml_corpus_tests.xz
mkdir -p /work/shared && ln -sfn $PWD/.corpus-d /work/shared/corpus
{ env LD_LIBRARY_PATH=.devbin/lib .devbin/ml_gpu_tests --gtest_filter='ComputeRaster*'
  env LD_LIBRARY_PATH=.devbin/lib .devbin/ml_corpus_tests --gtest_filter='*ComputeRaster*'; } 2>&1 | grep -v "^\[ RUN\|^\[--" > $OUT/ids.txt
kill %1
tar czf $OUT/logs.tgz -C /tmp timing.log accuracy.log smclock.csv
