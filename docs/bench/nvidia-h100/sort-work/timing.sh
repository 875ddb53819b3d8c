#!/usr/bin/env bash
# Issue 32's list sort over listed lists, before and after on one machine in one command: the
# atrium as it ships (glass on), GGX, 2560x1440, lights of radius overlap:32, exact lists,
# atrium-set, median of 30 frames after 5. Before: main at 58b81f9 (.devbin-old: a workgroup per
# list); after: .devbin (a classify pass lists the lists of two or more entries, the sorts are
# dispatched indirectly). Then byte equality of both binaries' frames (the sorted lists are the
# same, so every frame must be).
set -u
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
for build in old new; do
  if [ $build = old ]; then M="env LD_LIBRARY_PATH=.devbin-old/lib .devbin-old/manylights"; else M="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"; fi
  $M bench $S --method forward-plus,deferred,visibility --lights 65536 --out $OUT --name $build-64k > $OUT/$build-64k.log 2>&1
  $M bench $S --method deferred,visibility --lights 1048576 --out $OUT --name $build-1m > $OUT/$build-1m.log 2>&1
  $M bench $S --method deferred,visibility --normal-cones on --lights 65536 --out $OUT --name $build-cones-64k > $OUT/$build-cones-64k.log 2>&1
  mkdir -p /tmp/frames/$build
  for m in forward-plus deferred visibility; do
    $M render --method $m --lights 65536 --size 2560x1440 --backend egl --out /tmp/frames/$build/$m.png > /dev/null 2>&1
    $M render --method $m --lights 65536 --size 2560x1440 --normal-cones --backend egl --out /tmp/frames/$build/$m-cones.png > /dev/null 2>&1
  done
done
kill %1
for f in /tmp/frames/old/*.png; do
  if cmp -s "$f" "/tmp/frames/new/$(basename "$f")"; then echo "identical $(basename "$f")"; else echo "DIFFERENT $(basename "$f")"; fi
done > $OUT/frames.txt
