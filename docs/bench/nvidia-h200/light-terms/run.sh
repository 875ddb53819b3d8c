#!/usr/bin/env bash
# Issue 30: the per-light shading terms (glsl/include/shading.glsl): the falloff from the squared
# distance, the light's direction by one inverse square root, GGX's D and Vis in one division;
# against main, on an H200 (nvidia-h200). Carry .gl, .corpus-glass (corpus/amd/gas_station alone) and:
#   .devbin-scan.txz  before: main (c005f13; 9f20e06 changed no shader)
#   .devbin-d2.txz    the change (manylights, ml_gpu_tests; built in /work/main/build)
# Part 2, the switches compiled in and the Lambert term per point, against part 1:
#   BUILDS='d2:.devbin-l1 v2:.devbin-v2' NEW=.devbin-v2 run.sh ...   (.devbin-l1: part 1 without its tests)
#   run.sh warm          a few seconds of frames, so that the SM clock has risen before a round
#   run.sh round <n>     targets.sweep.json (every scene of the targets but Sponza), main then the change
#   run.sh atrium <n>    atrium.sweep.json (the targets' atrium rows), main then the change
#   run.sh headline      the README's results table: main, then the change
#   run.sh sponza <n>    sponza.sweep.json: Sponza's four cameras at 1,048,576 lights, both rasters, main then
#                        the change. Sponza's 14 MB do not travel beside the tree and the builds: one call
#                        carries .corpus-sponza alone and copies it to /root, the next (the machine still
#                        warm) carries the builds and takes it back from there.
#   run.sh targets-4m    4,194,304 lights at 3840x2160 (list-sync's sweep), main then the change
#   run.sh tests         the GPU tests that hold methods to naive and the shading to its CPU mirror, on the change
#   run.sh accuracy      tools/gpu-accuracy on the atrium and the gas station, the change
#   run.sh golden        the golden-image tests (llvmpipe's frames) on the H200, main's and the change's
set -u
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
# Every build packs the same libraries (tools/pack-for-gpu).
export LD_LIBRARY_PATH=$(ls -d $PWD/.devbin*/lib | head -1)
S=docs/bench/nvidia-h200/light-terms
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
BUILDS=${BUILDS:-'main:.devbin-scan new:.devbin-d2'}
NEW=${NEW:-.devbin-d2}  # the change the tests and the accuracy run
case "$1" in
warm)
  timeout 60 $NEW/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --warmup 5 --timed-frames 600 \
    --backend egl --out $OUT/warm --name warm > /dev/null 2>&1
  rm -rf $OUT/warm ;;
round)
  for build in $BUILDS; do
    timeout 240 ${build#*:}/manylights bench --sweep $S/targets.sweep.json --backend egl --out $OUT --name targets-${build%:*}-$2 \
      > $OUT/targets-${build%:*}-$2.log 2>&1
  done ;;
atrium)
  for build in $BUILDS; do
    timeout 240 ${build#*:}/manylights bench --sweep $S/atrium.sweep.json --backend egl --out $OUT --name atrium-${build%:*}-$2 \
      > $OUT/atrium-${build%:*}-$2.log 2>&1
  done ;;
sponza)
  [ -d .corpus-sponza ] || cp -r /root/.corpus-sponza .
  for build in $BUILDS; do
    timeout 240 ${build#*:}/manylights bench --sweep $S/sponza.sweep.json --backend egl --out $OUT --name sponza-${build%:*}-$2 \
      > $OUT/sponza-${build%:*}-$2.log 2>&1
  done ;;
targets-4m)
  for build in $BUILDS; do
    timeout 150 ${build#*:}/manylights bench --sweep docs/bench/nvidia-h100/list-sync/targets-4m/targets-4m.sweep.json \
      --backend egl --out $OUT --name targets-4m-${build%:*} > $OUT/targets-4m-${build%:*}.log 2>&1
  done ;;
headline)
  # The README's results table (--preset scale, atrium-set); every method shades with the terms.
  P='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
  for build in $BUILDS; do
    M=${build#*:}/manylights L=${build%:*}
    $M bench $P --method naive,forward-plus,deferred,visibility --lights 1024 --out $OUT --name headline-1k-$L > $OUT/headline-1k-$L.log 2>&1
    $M bench $P --method forward-plus,deferred,visibility --lights 65536 --out $OUT --name headline-64k-$L > $OUT/headline-64k-$L.log 2>&1
    $M bench $P --method deferred,visibility --lights 1048576 --out $OUT --name headline-1m-$L > $OUT/headline-1m-$L.log 2>&1
    for n in 1024:1k 65536:64k 1048576:1m; do
      $M bench $P --method visibility --vis-raster compute --lights ${n%:*} --out $OUT --name compute-${n#*:}-$L > $OUT/compute-${n#*:}-$L.log 2>&1
    done
  done ;;
tests)
  # The paths the test binary was built with: the executable beside it.
  mkdir -p /work/main/build && ln -sf $PWD/$NEW/manylights /work/main/build/manylights
  ML_TEST_TMP=/tmp/ml-tests timeout 400 $NEW/ml_gpu_tests \
    --gtest_filter='*ClusteredAccuracy*:*ExactGBuffer*:*WorkgroupCulledLighting*:*MixedLights*:*SpotLights*:*StochasticCutoff*:*LightSumTest*:*SpecularOff*:SpecularSwitch.*:GlassCapture.*:*Transparen*:*GoldenImage*:NaiveForwardTest.*:*BenchPhysicalReference*' 2>&1 \
    | grep -v "^\[ RUN\|^\[--" > $OUT/gpu-tests.txt ;;
golden)
  # The golden images are llvmpipe's frames: does the H200 drift from them with main's shading too?
  for build in $BUILDS; do
    mkdir -p /work/main/build && ln -sf $PWD/${build#*:}/manylights /work/main/build/manylights
    ML_TEST_TMP=/tmp/ml-tests-${build%:*} timeout 200 ${build#*:}/ml_gpu_tests --gtest_filter='*GoldenImage*' 2>&1 \
      | grep -v "^\[ RUN\|^\[--" > $OUT/golden-${build%:*}.txt
  done ;;
accuracy)
  timeout 400 python3 tools/gpu-accuracy --manylights $NEW/manylights --corpus .corpus-glass/corpus \
    --only atrium,GasStation --out $OUT/accuracy > $OUT/accuracy.log 2>&1
  echo "gpu-accuracy exit $?" >> $OUT/accuracy.log
  rm -rf $OUT/accuracy/worst ;;
esac
