#!/usr/bin/env bash
# Generated lights in Morton order of their positions (issue 30), before and after on one
# machine (nvidia-h100-x1) in one command: one binary (scratch.patch), the order chosen by
# ML_SCRATCH_MORTON. Carry .devbin.txz, .gl and .corpus-f. Everything lands in $OUT/order.tgz.
set -u
D=docs/bench/nvidia-h100/light-order
FINAL=$OUT
OUT=/tmp/results/order
mkdir -p $OUT
[ -d .devbin ] || tar xJf .devbin.txz
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
M="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
for pass in a b; do
  $M bench --sweep $D/targets.sweep.json --backend egl --out $OUT --name index-$pass > $OUT/index-$pass.log 2>&1
  ML_SCRATCH_MORTON=1 $M bench --sweep $D/targets.sweep.json --backend egl --out $OUT --name morton-$pass > $OUT/morton-$pass.log 2>&1
done
$M bench --sweep $D/4m.sweep.json --backend egl --out $OUT --name index-4m > $OUT/index-4m.log 2>&1
ML_SCRATCH_MORTON=1 $M bench --sweep $D/4m.sweep.json --backend egl --out $OUT --name morton-4m > $OUT/morton-4m.log 2>&1
tar czf $FINAL/order.tgz -C /tmp/results order
