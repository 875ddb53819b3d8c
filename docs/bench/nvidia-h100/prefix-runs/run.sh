#!/usr/bin/env bash
# Issue 30: the prefix sum in runs of 8 elements an invocation, on the H100 (nvidia-h100-x1).
# Carry .gl, .devbin.txz (03fde41 with runs.patch: manylights, ml_gpu_tests), .devbin-old.txz
# (03fde41: its manylights alone, run with .devbin's libraries) and .corpus-gas
# (corpus/amd/gas_station).
#   run.sh <n>   scan.sweep.json with before (-old) and after (-new) in turn, named -<n>
#   run.sh tests the prefix sum's and the glass capture's GPU tests (tests.txt)
set -u
D=docs/bench/nvidia-h100/prefix-runs
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
case "$1" in
tests)
  .devbin/ml_gpu_tests --gtest_filter='Sizes/PrefixSumTest.*:Sizes/RadixSortTest.*:GlassCapture.*:Grids/LightAssignment.*' 2>&1 \
    | grep -v "^\[ RUN\|^\[--" > $OUT/tests.txt ;;
*)
  for build in -old ""; do
    label=${build:--new}
    timeout 200 .devbin$build/manylights bench --sweep $D/scan.sweep.json --backend egl --out $OUT --name scan$label-$1 \
      > $OUT/scan$label-$1.log 2>&1
  done ;;
esac
