#!/usr/bin/env bash
# Issue 29, before and after on one machine in one command: the atrium as it ships (glass on),
# GGX (the default), 2560x1440, lights of radius overlap:32, exact lists, atrium-set, median of
# 30 frames after 5. Before: main at bbdf756 (.devbin-old, packed G-buffer by default); after:
# this branch (.devbin: exact G-buffer by default, texture coordinates rebuilt in every pass),
# and after with --gbuffer packed to show what each of the two changes costs.
set -u
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
for build in old new; do
  if [ $build = old ]; then M="env LD_LIBRARY_PATH=.devbin-old/lib .devbin-old/manylights"; else M="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"; fi
  $M bench $S --method naive,forward-plus,deferred,visibility --lights 1024 --out $OUT --name $build-1k > $OUT/$build-1k.log 2>&1
  $M bench $S --method forward-plus,deferred,visibility --lights 65536 --out $OUT --name $build-64k > $OUT/$build-64k.log 2>&1
  $M bench $S --method deferred,visibility --lights 1048576 --out $OUT --name $build-1m > $OUT/$build-1m.log 2>&1
done
M="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
$M bench $S --method deferred,visibility --gbuffer packed --lights 65536 --out $OUT --name new-packed-64k > $OUT/new-packed-64k.log 2>&1
kill %1
# The million-light anomaly (docs/benchmarks.md): every draw of an 8-draw stochastic point, per method.
if [ -z "${SKIP_DRAWS:-}" ]; then
mkdir -p /tmp/draws
C='--lights 1048576 --light-intensity 0.0009765625 --size 640x360 --cutoff stochastic --light-cutoff 0.005 --backend egl'
for m in visibility deferred forward-plus; do
  for k in 1 2 3 4 5 6 7 8; do $M render $C --method $m --accumulate $k --out /tmp/draws/x.png --out-float /tmp/draws/$m-$k.pfm > /dev/null 2>>$OUT/draws.err; done
done
python3 docs/bench/nvidia-h100/exactness/stochastic_draws.py /tmp/draws 8 visibility deferred forward-plus > $OUT/draws.txt 2>&1
fi
# The same against the physical reference on several frames: one draw and the mean of 8.
for f in 60 61 62 63 64 65; do
  $M bench --sweep docs/bench/nvidia-h100/exactness/stochastic-frames.sweep.json --frame $f --backend egl --out $OUT --name stochastic-frame$f > $OUT/stochastic-frame$f.log 2>&1
done
