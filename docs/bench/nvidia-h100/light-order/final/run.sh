#!/usr/bin/env bash
# On main with the Morton order (.devbin): the README's results table (as
# assign-runs/run.sh headline) and issue 30's target rows (sort-chunks' sweep), on one machine
# (nvidia-h100-x1) in one command. Carry .devbin.txz, .gl and .corpus-f. Everything lands in
# $OUT/final.tgz.
set -u
FINAL=$OUT
OUT=/tmp/results/final
mkdir -p $OUT
[ -d .devbin ] || tar xJf .devbin.txz
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
NEW="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
$NEW bench $S --method naive,forward-plus,deferred,visibility --lights 1024 --out $OUT --name headline-1k > $OUT/headline-1k.log 2>&1
$NEW bench $S --method forward-plus,deferred,visibility --lights 65536 --out $OUT --name headline-64k > $OUT/headline-64k.log 2>&1
$NEW bench $S --method deferred,visibility --lights 1048576 --out $OUT --name headline-1m > $OUT/headline-1m.log 2>&1
tar czf $FINAL/final.tgz -C /tmp/results final  # the table, should the sweep run out of time
$NEW bench --sweep docs/bench/nvidia-h100/sort-chunks/targets.sweep.json --backend egl --out $OUT --name targets > $OUT/targets.log 2>&1
tar czf $FINAL/final.tgz -C /tmp/results final
