#!/usr/bin/env bash
# The glass pass taken apart on the gas station (issue 30): main at 747f713 with experiments.patch,
# run with ML_EXPERIMENT=<n> for each n of EXPS (rounds: EXPS="0 1 2 3 4 0", "0 5 0 5", "0 8 9 0 8 9").
# Carry .gl, .devbin.txz (that build) and .corpus-gas.
set -u
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
timeout 60 .devbin/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --warmup 5 --timed-frames 300 --backend egl --out $OUT/warm --name warm > /dev/null 2>&1; rm -rf $OUT/warm
for e in ${EXPS:-0 1 2 3 4 0}; do
  ML_EXPERIMENT=$e timeout 120 .devbin/manylights bench --sweep docs/bench/nvidia-h100/cooperative-rounds/gas.sweep.json --backend egl --out $OUT --name exp$e-$RANDOM > $OUT/exp$e.log 2>&1
done
cd $OUT && tar czf all.tgz --exclude=all.tgz * && find . -mindepth 1 -not -name all.tgz -delete
