#!/usr/bin/env bash
# The lighting pass's shading work counted and its rate measured (issue 30): one binary with
# scratch.patch, on one machine (nvidia-h100-x1) in one command. ML_SCRATCH_COUNT counts, per
# frame, the lights each point shades (`evals`), those that add anything (`hits`) and the lit
# points, printed to the log (its read-back stalls the frame: no timing from those runs);
# ML_SCRATCH_DENSE shades every staged light of the list, not only those that reach the box.
# Carry .devbin.txz, .gl and .corpus-f. Everything lands in $OUT/count.tgz.
set -u
D=docs/bench/nvidia-h100/lighting-tiles
FINAL=$OUT
OUT=/tmp/results/count
mkdir -p $OUT
[ -d .devbin ] || tar xJf .devbin.txz
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
M="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
ML_SCRATCH_COUNT=1 $M bench --sweep $D/lighting.sweep.json --backend egl --out $OUT --name count > $OUT/count.log 2>&1
ML_SCRATCH_COUNT=1 ML_SCRATCH_DENSE=1 $M bench --sweep $D/lighting.sweep.json --backend egl --out $OUT --name count-dense > $OUT/count-dense.log 2>&1
for pass in a b; do
  $M bench --sweep $D/lighting.sweep.json --backend egl --out $OUT --name full-$pass > $OUT/full-$pass.log 2>&1
  ML_SCRATCH_DENSE=1 $M bench --sweep $D/lighting.sweep.json --backend egl --out $OUT --name dense-$pass > $OUT/dense-$pass.log 2>&1
done
tar czf $FINAL/count.tgz -C /tmp/results count
