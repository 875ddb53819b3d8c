#!/usr/bin/env bash
# Issue 30: the glass's shading dispatched over the tiles that hold glass (glsl/glass_shade.comp's
# kListTiles lists them; kShadeShallowTiles runs an indirect dispatch over them) instead of a
# workgroup per screen tile, against main (the overlap of ../glass-overlap), on an H200
# (nvidia-h200). Carry .gl, .corpus-glass (corpus/amd/gas_station alone) and:
#   .devbin-ov.txz   before: main at 96bdde4, whose code eff01e1 still is (../glass-overlap's build)
#   .devbin-new.txz  the change (manylights, ml_gpu_tests; built in /work/main/build)
#   run.sh warm          a few seconds of frames, so that the SM clock has risen before a round
#   run.sh round <n>     ../glass-layers' gas and atrium sweeps, main then the change
#   run.sh targets-4m    4,194,304 lights at 3840x2160 (list-sync's sweep), main then the change
#   run.sh headline      the README's results table but naive: main, then the change
#   run.sh tests         the glass's GPU tests on the change (the split against one pass, bit for bit)
#   run.sh accuracy      tools/gpu-accuracy on the atrium and the gas station, the change
set -u
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
export LD_LIBRARY_PATH=$PWD/.devbin-new/lib
S=docs/bench/nvidia-h200/glass-layers
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
BUILDS='main:.devbin-ov new:.devbin-new'
case "$1" in
warm)
  timeout 60 .devbin-new/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --warmup 5 --timed-frames 600 \
    --backend egl --out $OUT/warm --name warm > /dev/null 2>&1
  rm -rf $OUT/warm ;;
round)
  for build in $BUILDS; do
    for s in gas atrium; do
      timeout 200 ${build#*:}/manylights bench --sweep $S/$s.sweep.json --backend egl --out $OUT --name $s-${build%:*}-$2 \
        > $OUT/$s-${build%:*}-$2.log 2>&1
    done
  done ;;
targets-4m)
  for build in $BUILDS; do
    timeout 150 ${build#*:}/manylights bench --sweep docs/bench/nvidia-h100/list-sync/targets-4m/targets-4m.sweep.json \
      --backend egl --out $OUT --name targets-4m-${build%:*} > $OUT/targets-4m-${build%:*}.log 2>&1
  done ;;
headline)
  # The README's results table (--preset scale, atrium-set) but naive, which splits nothing.
  P='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
  for build in $BUILDS; do
    M=${build#*:}/manylights L=${build%:*}
    $M bench $P --method forward-plus,deferred,visibility --lights 1024 --out $OUT --name headline-1k-$L > $OUT/headline-1k-$L.log 2>&1
    $M bench $P --method forward-plus,deferred,visibility --lights 65536 --out $OUT --name headline-64k-$L > $OUT/headline-64k-$L.log 2>&1
    $M bench $P --method deferred,visibility --lights 1048576 --out $OUT --name headline-1m-$L > $OUT/headline-1m-$L.log 2>&1
    for n in 1024:1k 65536:64k 1048576:1m; do
      $M bench $P --method visibility --vis-raster compute --lights ${n%:*} --out $OUT --name compute-${n#*:}-$L > $OUT/compute-${n#*:}-$L.log 2>&1
    done
  done ;;
tests)
  # The paths the test binary was built with: the executable beside it.
  mkdir -p /work/main/build && ln -sf $PWD/.devbin-new/manylights /work/main/build/manylights
  ML_TEST_TMP=/tmp/ml-tests timeout 400 .devbin-new/ml_gpu_tests --gtest_filter='GlassCapture.*:*Transparen*' 2>&1 \
    | grep -v "^\[ RUN\|^\[--" > $OUT/gpu-tests.txt ;;
accuracy)
  timeout 400 python3 tools/gpu-accuracy --manylights .devbin-new/manylights --corpus .corpus-glass/corpus \
    --only atrium,GasStation --out $OUT/accuracy > $OUT/accuracy.log 2>&1
  echo "gpu-accuracy exit $?" >> $OUT/accuracy.log
  rm -rf $OUT/accuracy/worst ;;
esac
