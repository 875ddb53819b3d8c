#!/usr/bin/env bash
# Every method's surface position on the pixel's ray (pixel_ray.glsl's pixelRayPoint), which the
# exact G-buffer layout now rebuilds to the bit, on the H100 (nvidia-h100-x1), in one command:
#   1. before/after timing, interleaved twice: the README's 65,536-light rows (deferred and the
#      visibility buffer, the atrium's four cameras); .devbin-old is main before the change,
#      .devbin after;
#   2. tools/gpu-accuracy after, on the frames whose defaults were farthest off naive (ToyCar's
#      nine, DamagedHelmet, boxes) and on the atrium, NormalTangentMirrorTest;
#   3. ml_gpu_tests after.
# Carry .devbin.txz, .devbin-old.txz, .gl and .corpus-kh. Everything lands in $OUT/ray-position.tgz.
set -u
FINAL=$OUT
OUT=/tmp/results/ray-position
mkdir -p $OUT
for b in .devbin .devbin-old; do [ -d $b ] || tar xJf $b.txz; done
[ -d .corpus-kh/corpus ] || (cd .corpus-kh && tar xJf khronos.txz)
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
pack() { tar czf $FINAL/ray-position.tgz -C /tmp/results ray-position; }
S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl --method deferred,visibility --lights 65536'
for pass in a b; do
  for b in old new; do
    bin=.devbin; [ $b = old ] && bin=.devbin-old
    env LD_LIBRARY_PATH=$bin/lib $bin/manylights bench $S --out $OUT --name timing-$b-$pass > $OUT/timing-$b-$pass.log 2>&1
  done
done
pack
export LD_LIBRARY_PATH=$PWD/.devbin/lib
timeout 240 python3 tools/gpu-accuracy --manylights .devbin/manylights --corpus $PWD/.corpus-kh/corpus \
  --only ToyCar,DamagedHelmet,boxes,atrium,NormalTangentMirrorTest --out $OUT/accuracy > $OUT/accuracy.log 2>&1
echo "gpu-accuracy exit $?" >> $OUT/exits.txt
pack
mkdir -p /work/main/build-test /work/shared
ln -sf $PWD/.devbin/manylights /work/main/build-test/manylights
ln -sfn $PWD/.corpus-kh/corpus /work/shared/corpus
ML_TEST_TMP=/tmp/gtest timeout 150 .devbin/ml_gpu_tests 2>&1 | grep -v "^\[ RUN\|^\[--" > $OUT/ml_gpu_tests.txt
echo "ml_gpu_tests exit ${PIPESTATUS[0]}" >> $OUT/exits.txt
pack
