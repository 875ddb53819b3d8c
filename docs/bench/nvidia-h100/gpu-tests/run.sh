#!/usr/bin/env bash
# Every GPU test binary on the H100 (nvidia-h100-x1), built from this commit (.devbin with
# ml_gpu_tests, ml_corpus_tests and ml_fullsize_tests), and a check of bench's SM clock column
# (read while the timed frames run) at the points whose clock the old reading caught idle.
# Carry .devbin.txz, .gl and .corpus-all (../shared's corpus/ and compressed/). Everything lands
# in $OUT/gpu-tests.tgz.
set -u
FINAL=$OUT
OUT=/tmp/results/gpu-tests
mkdir -p $OUT/images
[ -d .devbin ] || tar xJf .devbin.txz
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
# The paths the test binaries were built with: the executable and ../shared.
mkdir -p /work/main/build-test /work/shared
ln -sf $PWD/.devbin/manylights /work/main/build-test/manylights
ln -sfn $PWD/.corpus-all/corpus /work/shared/corpus
ln -sfn $PWD/.corpus-all/compressed /work/shared/compressed
export LD_LIBRARY_PATH=$PWD/.devbin/lib ML_TEST_TMP=$OUT/images
pack() { tar czf $FINAL/gpu-tests.tgz -C /tmp/results gpu-tests; }
for t in ml_gpu_tests ml_corpus_tests ml_fullsize_tests; do
  timeout 200 .devbin/$t 2>&1 | grep -v "^\[ RUN\|^\[--" > $OUT/$t.txt
  echo "$t exit ${PIPESTATUS[0]}" >> $OUT/exits.txt
  pack
done
B=".devbin/manylights bench --backend egl --warmup 5 --timed-frames 30 --method visibility --camera atrium-set --radius overlap:32"
$B --lights 4194304 --size 3840x2160 --vis-raster compute --out $OUT --name clock-4m > $OUT/clock-4m.log 2>&1
pack
