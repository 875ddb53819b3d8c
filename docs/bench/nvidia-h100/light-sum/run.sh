#!/usr/bin/env bash
# Issue 30's list lever on the H100 (nvidia-h100-x1): --light-sum float (lists sorted) against
# --light-sum fixed (no sort) on one binary, timing and accuracy against naive, then the fixed
# sum's frames rendered twice and compared byte for byte. Carry .devbin, .gl, .corpus-d (Sponza)
# and .corpus-e (the gas station).
set -u
D=docs/bench/nvidia-h100/light-sum
B=.devbin
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
for sweep in timing accuracy; do
  env LD_LIBRARY_PATH=$B/lib $B/manylights bench --sweep $D/$sweep.sweep.json --backend egl --out $OUT --name $sweep > /tmp/$sweep.log 2>&1
done
for run in 1 2; do
  for m in visibility deferred forward-plus; do
    env LD_LIBRARY_PATH=$B/lib $B/manylights render --scene atrium --method $m --lights 65536 --size 2560x1440 --backend egl \
      --light-sum fixed --out-float /tmp/$m-$run.pfm --out /tmp/$m-$run.png > /dev/null 2>&1
  done
done
for m in visibility deferred forward-plus; do
  if cmp -s /tmp/$m-1.pfm /tmp/$m-2.pfm; then echo "identical $m"; else echo "DIFFERENT $m"; fi
done > $OUT/determinism.txt
tar czf $OUT/logs.tgz -C /tmp timing.log accuracy.log
