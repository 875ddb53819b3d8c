#!/usr/bin/env bash
# Long light lists sorted in chunks merged by rank (issue 30), before and after on one machine
# (nvidia-h100-x1) in one command. Before: main at 13dcc01 (.devbin-old); after: the chunks
# (.devbin, with ml_gpu_tests). Carry .devbin.txz, .devbin-old.txz, .gl and .corpus-f (Sponza
# and the gas station). Everything lands in $OUT/sort.tgz.
set -u
D=docs/bench/nvidia-h100/sort-chunks
LABEL=sort
FINAL=$OUT
OUT=/tmp/results/$LABEL
mkdir -p $OUT
for b in .devbin .devbin-old; do [ -d $b ] || tar xJf $b.txz; done
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
OLD="env LD_LIBRARY_PATH=.devbin-old/lib .devbin-old/manylights"
NEW="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
# Frames: the sorted lists are the same, so every method's frame must be byte-identical; the gas
# station at a million lights has lists past shared memory.
for m in forward-plus deferred visibility; do
  for build in old new; do
    M=OLD; [ $build = new ] && M=NEW
    ${!M} render --scene atrium --method $m --lights 65536 --size 1280x720 --backend egl --out /tmp/$build-$m.png > /dev/null 2>&1
  done
  cmp -s /tmp/old-$m.png /tmp/new-$m.png && echo "$m atrium 65536 lights 1280x720: byte-identical" || echo "$m atrium 65536 lights 1280x720: DIFFERENT"
done > $OUT/frames.txt
for m in deferred visibility; do
  for build in old new; do
    M=OLD; [ $build = new ] && M=NEW
    ${!M} render --scene .corpus-f/amd/gas_station/GasStation.gltf --method $m --lights 1048576 --light-radius overlap:32 --size 2560x1440 --backend egl --out /tmp/$build-gas-$m.png > /dev/null 2>&1
  done
  cmp -s /tmp/old-gas-$m.png /tmp/new-gas-$m.png && echo "$m gas station 1048576 lights 2560x1440: byte-identical" || echo "$m gas station 1048576 lights 2560x1440: DIFFERENT"
done >> $OUT/frames.txt
# Before and after twice, interleaved, as the H100's clock falls on some points.
for pass in a b; do
  $OLD bench --sweep $D/targets.sweep.json --backend egl --out $OUT --name targets-old-$pass > $OUT/targets-old-$pass.log 2>&1
  $NEW bench --sweep $D/targets.sweep.json --backend egl --out $OUT --name targets-new-$pass > $OUT/targets-new-$pass.log 2>&1
done
env LD_LIBRARY_PATH=.devbin/lib .devbin/ml_gpu_tests --gtest_filter='GpuTest.ListSort*:Sort/*:Grids/LightAssignment.*' 2>&1 \
  | grep -v "^\[ RUN\|^\[--" > $OUT/gtest.txt
tar czf $FINAL/$LABEL.tgz -C /tmp/results $LABEL
