#!/usr/bin/env bash
# The GPU test binaries and the accuracy routine on the H100 (nvidia-h100-x1), built from this
# commit (.devbin with ml_gpu_tests, ml_corpus_tests, ml_fullsize_tests), in two calls, since the
# corpus and the tree do not travel together (64 MiB a call):
#   run.sh amd      carry .devbin.txz .gl .corpus-amd (corpus/amd): ml_gpu_tests; the corpus
#                   and full-size tiers' AMD frames; tools/gpu-accuracy on the built-in scenes,
#                   Sponza and the gas station; bench's SM clock at four million lights
#   run.sh khronos  carry .devbin.txz .gl .corpus-kh (khronos.txz: corpus/khronos, playcanvas,
#                   compressed): the GPU tests the first call found failing, again (after their
#                   fixes) or with the files they need; the rest of both tiers and of the
#                   accuracy routine; Forward+ --active-only against naive (active-only.sh)
# Everything lands in $OUT/gpu-tests-PART.tgz and $OUT/pictures-PART.tgz.
set -u
PART=$1
FINAL=$OUT
OUT=/tmp/results/gpu-tests-$PART
mkdir -p $OUT/images
[ -d .devbin ] || tar xJf .devbin.txz
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
CORPUS=$PWD/.corpus-${PART:0:2}/corpus; [ $PART = amd ] && CORPUS=$PWD/.corpus-amd/corpus
if [ $PART = khronos ]; then (cd .corpus-kh && tar xJf khronos.txz); fi
# The paths the test binaries were built with: the executable and ../shared.
mkdir -p /work/main/build-test /work/shared
ln -sf $PWD/.devbin/manylights /work/main/build-test/manylights
ln -sfn $CORPUS /work/shared/corpus
[ $PART = khronos ] && ln -sfn $PWD/.corpus-kh/compressed /work/shared/compressed
export LD_LIBRARY_PATH=$PWD/.devbin/lib ML_TEST_TMP=$OUT/images
# Text in one archive, pictures (failing tests' images, the worst frames) in another: at most
# 16 MiB a file comes back.
pack() {
  tar czf $FINAL/gpu-tests-$PART.tgz -C /tmp/results --exclude=images --exclude=worst --exclude=diffs gpu-tests-$PART
  tar czf $FINAL/pictures-$PART.tgz -C /tmp/results --exclude='*.csv' --exclude='*.json' --exclude='*.txt' --exclude='*.log' gpu-tests-$PART
}
gtest() {  # binary, filter
  timeout 240 .devbin/$1 --gtest_filter="$2" 2>&1 | grep -v "^\[ RUN\|^\[--" > $OUT/$1.txt
  echo "$1 exit ${PIPESTATUS[0]}" >> $OUT/exits.txt
  pack
}
if [ $PART = amd ]; then
  gtest ml_gpu_tests '*'
  gtest ml_corpus_tests '*sponza*:*Sponza*:*gas*:*Gas*'
  gtest ml_fullsize_tests '*Sponza*:*GasStation*'
  timeout 240 python3 tools/gpu-accuracy --manylights .devbin/manylights --corpus $CORPUS --out $OUT/accuracy > $OUT/accuracy.log 2>&1
  echo "gpu-accuracy exit $?" >> $OUT/exits.txt
  pack
  B=".devbin/manylights bench --backend egl --warmup 5 --timed-frames 30 --method visibility --camera atrium-set --light-radius overlap:32"
  $B --lights 4194304 --size 3840x2160 --vis-raster compute --out $OUT --name clock-4m > $OUT/clock-4m.log 2>&1
else
  gtest ml_gpu_tests '*NormalCones*:*ActiveOnly*:Msaa.*:VisibilityIds.*:FirstContact.*'
  mv $OUT/ml_gpu_tests.txt $OUT/ml_gpu_tests-rerun.txt
  gtest ml_corpus_tests '-*sponza*:*Sponza*:*gas*:*Gas*'
  gtest ml_fullsize_tests '-*Sponza*:*GasStation*'
  bash docs/bench/nvidia-h100/gpu-tests/active-only.sh $OUT; pack
  STEMS=$(find $CORPUS -name '*.gltf' -o -name '*.glb' | xargs -n1 basename | sed 's/\.gl[tb]f\?$//' | sort -u | paste -sd,)
  timeout 300 python3 tools/gpu-accuracy --manylights .devbin/manylights --corpus $CORPUS --only "$STEMS" --out $OUT/accuracy > $OUT/accuracy.log 2>&1
  echo "gpu-accuracy exit $?" >> $OUT/exits.txt
fi
pack
