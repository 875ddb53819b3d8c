#!/usr/bin/env bash
# Issue 30: reversed depth on the H100 (nvidia-h100-x1). Carry .devbin.txz (main with reversed
# depth: manylights, ml_gpu_tests, ml_corpus_tests), .gl and .corpus-amd (corpus/amd: Sponza and
# the gas station); for `targets`, also .devbin-old.txz (main before it, 98bf263: its manylights
# alone, run with .devbin's libraries).
#   run.sh accuracy  every method against naive at 2560x1440 (accuracy.sweep.json), the visibility
#                    buffer by the hardware and by the compute raster; the compute raster's ids
#                    against the hardware's (ComputeRaster*, VisibilityIds*, the corpus's AMD files)
#   run.sh targets   issue 30's targets before and after (targets.sweep.json), both rasters;
#                    raster-floors
#   run.sh headline  the README's results table (--preset scale, every method in its defaults,
#                    atrium-set), and the visibility buffer with the compute raster
#   run.sh routine amd|khronos   the GPU accuracy routine (tools/gpu-accuracy: every method and
#                    layout against naive) on the built-in scenes and corpus/amd, with ml_gpu_tests
#                    (amd); on corpus/khronos and playcanvas (khronos: carry .corpus-kh, khronos.txz)
# Everything lands in $OUT/LABEL.tgz (pictures: $OUT/LABEL-pictures.tgz).
set -u
D=docs/bench/nvidia-h100/reversed-depth
LABEL=$1${2:+-$2}
FINAL=$OUT
OUT=/tmp/results/$LABEL
mkdir -p $OUT/images
for b in .devbin .devbin-old; do [ -d $b ] || [ ! -f $b.txz ] || tar xJf $b.txz; done
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
binary() { echo "env LD_LIBRARY_PATH=.devbin/lib .devbin${1:-}/manylights"; }
case "$1" in
accuracy)
  $(binary) bench --sweep $D/accuracy.sweep.json --backend egl --out $OUT --name accuracy > $OUT/accuracy.log 2>&1
  # The paths the test binaries were built with: the executable and ../shared.
  mkdir -p /work/main/build-test /work/shared
  ln -sf $PWD/.devbin/manylights /work/main/build-test/manylights
  ln -sfn $PWD/.corpus-amd/corpus /work/shared/corpus
  export LD_LIBRARY_PATH=$PWD/.devbin/lib ML_TEST_TMP=$OUT/images
  { timeout 200 .devbin/ml_gpu_tests --gtest_filter='ComputeRaster*:VisibilityIds*'
    timeout 200 .devbin/ml_corpus_tests --gtest_filter='*ComputeRaster*GasStation*:*ComputeRaster*Sponza*'; } 2>&1 | grep -v "^\[ RUN\|^\[--" > $OUT/ids.txt ;;
targets)
  for build in -old ""; do
    $(binary $build) bench --sweep $D/targets.sweep.json --backend egl --out $OUT --name targets${build:--new} > $OUT/targets${build:--new}.log 2>&1
  done
  $(binary) raster-floors --scene atrium --camera atrium-set --size 2560x1440 --backend egl --csv $OUT/raster-floors.csv > $OUT/floors.log 2>&1 ;;
headline)
  S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
  M=$(binary)
  $M bench $S --method naive,forward-plus,deferred,visibility --lights 1024 --out $OUT --name headline-1k > $OUT/headline-1k.log 2>&1
  $M bench $S --method forward-plus,deferred,visibility --lights 65536 --out $OUT --name headline-64k > $OUT/headline-64k.log 2>&1
  $M bench $S --method deferred,visibility --lights 1048576 --out $OUT --name headline-1m > $OUT/headline-1m.log 2>&1
  for n in 1024:1k 65536:64k 1048576:1m; do
    $M bench $S --method visibility --vis-raster compute --lights ${n%:*} --out $OUT --name compute-${n#*:} > $OUT/compute-${n#*:}.log 2>&1
  done ;;
routine)
  mkdir -p /work/main/build-test /work/shared
  ln -sf $PWD/.devbin/manylights /work/main/build-test/manylights
  export LD_LIBRARY_PATH=$PWD/.devbin/lib ML_TEST_TMP=$OUT/images
  if [ $2 = amd ]; then
    CORPUS=$PWD/.corpus-amd/corpus; ln -sfn $CORPUS /work/shared/corpus
    timeout 240 .devbin/ml_gpu_tests 2>&1 | grep -v "^\[ RUN\|^\[--" > $OUT/ml_gpu_tests.txt
    timeout 300 python3 tools/gpu-accuracy --manylights .devbin/manylights --corpus $CORPUS --out $OUT/accuracy > $OUT/accuracy.log 2>&1
  else
    (cd .corpus-kh && tar xJf khronos.txz); CORPUS=$PWD/.corpus-kh/corpus
    STEMS=$(find $CORPUS -name '*.gltf' -o -name '*.glb' | xargs -n1 basename | sed 's/\.gl[tb]f\?$//' | sort -u | paste -sd,)
    timeout 540 python3 tools/gpu-accuracy --manylights .devbin/manylights --corpus $CORPUS --only "$STEMS" --out $OUT/accuracy > $OUT/accuracy.log 2>&1
  fi
  echo "gpu-accuracy exit $?" >> $OUT/accuracy.log
  tar czf $FINAL/$LABEL-pictures.tgz -C /tmp/results --exclude='*.csv' --exclude='*.json' --exclude='*.txt' --exclude='*.log' $LABEL
  rm -rf $OUT/images $OUT/accuracy/worst ;;
esac
tar czf $FINAL/$LABEL.tgz -C /tmp/results $LABEL
