#!/usr/bin/env bash
# Issue 30: the compute raster's finish pass in row strips of 256 pixels, on the H100
# (nvidia-h100-x1). Carry .gl, .devbin.txz (main at 825224a: manylights, ml_gpu_tests,
# ml_corpus_tests), .devbin-old.txz (55574a2, 8x8 tiles: its manylights alone, run with .devbin's
# libraries) and .corpus-amd (corpus/amd).
#   run.sh targets   issue 30's targets with the compute raster, before, after, before, after
#                    (targets.sweep.json), and raster-floors at 2560x1440 and 3840x2160 both ways
#   run.sh headline  the README's row for `visibility --vis-raster compute` (--preset scale,
#                    atrium-set, 1,024 / 65,536 / 1,048,576 lights), on 825224a
#   run.sh tests     every GPU test (gpu-tests.txt), and the compute raster's ids against the
#                    hardware's (ComputeRaster*, VisibilityIds*, the corpus's AMD files: tests.txt)
# The workgroup shapes compared (variants/) came from a throwaway build, variants/variants.diff on
# 55574a2, picked by ML_FINISH_VARIANT: 0 8x8, 1 8x8 without the reset (timing only: the next frame
# is wrong), 2 32x8, 3 16x16, 4 64x4, 5 128x2, 6 256x1; and, in a first round, the reset by
# glClearNamedBufferData after the pass instead of in it.
set -u
D=docs/bench/nvidia-h100/raster-finish
for b in .devbin .devbin-old; do [ -d $b ] || tar xJf $b.txz; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
case "$1" in
targets)
  n=0
  for build in -old "" -old ""; do
    n=$((n + 1)); label=${build:--new}
    .devbin$build/manylights bench --sweep $D/targets.sweep.json --backend egl --out $OUT --name targets$label-$n > $OUT/targets$label-$n.log 2>&1
  done
  for build in -old ""; do
    for size in 2560x1440 3840x2160; do
      .devbin$build/manylights raster-floors --scene atrium --camera atrium-set --size $size --backend egl \
        --csv $OUT/floors${build:--new}-$size.csv > /dev/null 2>&1
    done
  done ;;
headline)
  S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
  mkdir -p $OUT/headline
  for n in 1024:1k 65536:64k 1048576:1m; do
    .devbin/manylights bench $S --method visibility --vis-raster compute --lights ${n%:*} --out $OUT/headline \
      --name compute-${n#*:} > $OUT/headline/compute-${n#*:}.log 2>&1
  done ;;
tests)
  mkdir -p /work/main/build-test /work/shared
  ln -sf $PWD/.devbin/manylights /work/main/build-test/manylights
  ln -sfn $PWD/.corpus-amd/corpus /work/shared/corpus
  timeout 300 .devbin/ml_gpu_tests 2>&1 | grep -v "^\[ RUN\|^\[--" > $OUT/gpu-tests.txt
  { timeout 200 .devbin/ml_gpu_tests --gtest_filter='ComputeRaster*:VisibilityIds*'
    timeout 200 .devbin/ml_corpus_tests --gtest_filter='*ComputeRaster*GasStation*:*ComputeRaster*Sponza*'; } 2>&1 | grep -v "^\[ RUN\|^\[--" > $OUT/tests.txt ;;
esac
