#!/usr/bin/env bash
# Issue 65's H100 record (nvidia-h100-x1), one command: the binary before the material extensions
# (.devbin-before, 921f644) and after (.devbin), tools/pack-for-gpu's output, .gl/ (Debian's GL
# dispatch, Embree and TBB packages) and .gpushared/ (../shared's corpus/amd/ and the khronos
# ClearCoatTest, ToyCar, AnisotropyStrengthTest and IridescenceSuzanne folders, with -nocoat,
# -nosheen, -noaniso and -noirid copies: the extension stripped from their materials) carried.
# ab.sweep.json with each binary in turn, lobes.sweep.json and accuracy.sweep.json with the new
# one, then ab.sweep.json again (the SM clock dips on a call's first points). Every file lands in $OUT/materials.tgz
# after each step, so a call cut short still returns what it ran.
set -u
D=docs/bench/nvidia-h100/material-extensions
R=/tmp/results/material-extensions
mkdir -p $R
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $R/gpu.txt
pack() { (cd /tmp/results && tar czf $OUT/materials.tgz material-extensions); }
step() {  # binary folder, sweep, name, seconds
  LD_LIBRARY_PATH=$1/lib timeout $4 $1/manylights bench --sweep $D/$2.sweep.json --backend egl --out $R --name $3 > $R/$3.log 2>&1
  echo "$3 rc $? $(date +%T) $(nvidia-smi --query-gpu=clocks.sm --format=csv,noheader)" >> $R/steps.txt
  pack
}
step .devbin-before ab before-a 80
step .devbin ab after-a 80
step .devbin lobes lobes 160
step .devbin accuracy accuracy 140
step .devbin-before ab before-b 60
step .devbin ab after-b 60
