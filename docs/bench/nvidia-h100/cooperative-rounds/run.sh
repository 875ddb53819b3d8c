#!/usr/bin/env bash
# Issue 30: cooperative list rounds (include/list_rounds.glsl), on the H100 (nvidia-h100-x1); not kept.
# Carry .gl, .corpus-gas or .corpus-sponza, and the builds, each packed as .devbin<suffix>.txz
# (tools/pack-for-gpu; besides .devbin, the manylights binary alone, run with .devbin's libraries):
#   .devbin       main with cooperative.patch (fma/ in this record; with `precise` sums instead of
#                 the fused multiply-add, precise/): ML_COOP=<n> in the environment sets the most
#                 served points a cooperative round takes (0: none, every round as before)
#   .devbin-old   main before it (747f713)
# A label names a build and its limit: old, or c<n> (.devbin with ML_COOP=n), or new (.devbin as built).
#   run.sh warm                     a few seconds of frames, so that the SM clock has risen before a round
#   run.sh gas <n> <label>...       gas.sweep.json with each label in turn, named gas-<label>-<n>
set -u
D=docs/bench/nvidia-h100/cooperative-rounds
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
run_label() {  # label sweep name
  case "$1" in
    old) timeout 280 .devbin-old/manylights bench --sweep $2 --backend egl --out $OUT --name $3 > $OUT/$3.log 2>&1 ;;
    new) timeout 280 .devbin/manylights bench --sweep $2 --backend egl --out $OUT --name $3 > $OUT/$3.log 2>&1 ;;
    c*) ML_COOP=${1#c} timeout 280 .devbin/manylights bench --sweep $2 --backend egl --out $OUT --name $3 > $OUT/$3.log 2>&1 ;;
  esac
}
case "$1" in
warm)
  timeout 60 .devbin/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --warmup 5 --timed-frames 300 \
    --backend egl --out $OUT/warm --name warm > /dev/null 2>&1
  rm -rf $OUT/warm ;;
gas)
  what=$1; n=$2; shift 2
  for label in "$@"; do run_label $label $D/$what.sweep.json $what-$label-$n; done ;;
esac
