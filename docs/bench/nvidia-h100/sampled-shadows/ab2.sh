#!/usr/bin/env bash
# Round 2: the steps whose results did not come back (too many files), into one archive.
set -u
D=docs/bench/nvidia-h100/sampled-shadows
R=/tmp/ab2; mkdir -p $R
export LD_LIBRARY_PATH=$PWD/.devbin-split/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $R/gpu.txt
pack() { tar czf $OUT/ab2.tgz -C /tmp ab2; }
stamp() { echo "$1 rc $2 $(date +%T) $(nvidia-smi --query-gpu=clocks.sm --format=csv,noheader)" | tee -a $R/steps.txt; pack; }
for way in split deferred-after; do
  timeout 100 .devbin-$way/manylights bench --sweep .gpushared/deferred.sweep.json --backend egl --out $R --name deferred-$way > $R/deferred-$way.log 2>&1
  stamp deferred-$way $?
done
for way in split cut16; do
  timeout 75 .devbin-$way/manylights bench --sweep $D/trace-pass.sweep.json --backend egl --out $R --name $way-c > $R/$way-c.log 2>&1
  stamp $way-c $?
done
