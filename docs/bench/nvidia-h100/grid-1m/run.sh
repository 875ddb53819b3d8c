#!/usr/bin/env bash
# The cluster grid's shape at issue 30's target rows, main at a7d6589 (.devbin-old), on one
# machine (nvidia-h100-x1) in one command. Carry .devbin-old.txz, .gl and .corpus-f.
# Everything lands in $OUT/grid.tgz.
set -u
D=docs/bench/nvidia-h100/grid-1m
FINAL=$OUT
OUT=/tmp/results/grid
mkdir -p $OUT
[ -d .devbin-old ] || tar xJf .devbin-old.txz
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
M="env LD_LIBRARY_PATH=.devbin-old/lib .devbin-old/manylights"
$M bench --sweep $D/grid.sweep.json --backend egl --out $OUT --name grid-a > $OUT/grid-a.log 2>&1
tar czf $FINAL/grid.tgz -C /tmp/results grid
