#!/usr/bin/env bash
# Issue 30: the prefix sum in one dispatch (glsl/prefix_sum.comp, a chained scan with decoupled
# look-back) against main (../glass-tiles' code), on an H200 (nvidia-h200). Carry .gl,
# .corpus-glass (corpus/amd/gas_station alone) and:
#   .devbin-new.txz   before: main at 798907c, whose code 0993c34 and f015981 still are
#   .devbin-scan.txz  the change (manylights, ml_gpu_tests; built in /work/main/build)
#   run.sh warm          a few seconds of frames, so that the SM clock has risen before a round
#   run.sh round <n>     targets.sweep.json (every scene of the targets), main then the change
#   run.sh variants <n>  atrium.sweep.json, each build of $BUILDS (the variants tried)
#   run.sh targets-4m    4,194,304 lights at 3840x2160 (list-sync's sweep), main then the change
#   run.sh headline      the README's results table but naive: main, then the change
#   run.sh frames        the same frames (PFM) from main and the change, compared byte for byte
#   run.sh tests         the scan's, the lists' and the glass's GPU tests on the change
#   run.sh accuracy      tools/gpu-accuracy on the atrium and the gas station, the change
set -u
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
# Every build packs the same libraries (tools/pack-for-gpu).
export LD_LIBRARY_PATH=$(ls -d $PWD/.devbin*/lib | head -1)
S=docs/bench/nvidia-h200/scan-lookback
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
BUILDS=${BUILDS:-'main:.devbin-new new:.devbin-scan'}
case "$1" in
warm)
  timeout 60 .devbin-scan/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --warmup 5 --timed-frames 600 \
    --backend egl --out $OUT/warm --name warm > /dev/null 2>&1
  rm -rf $OUT/warm ;;
round)
  for build in $BUILDS; do
    timeout 240 ${build#*:}/manylights bench --sweep $S/targets.sweep.json --backend egl --out $OUT --name targets-${build%:*}-$2 \
      > $OUT/targets-${build%:*}-$2.log 2>&1
  done ;;
variants)
  for build in $BUILDS; do
    timeout 240 ${build#*:}/manylights bench --sweep $S/atrium.sweep.json --backend egl --out $OUT --name atrium-${build%:*}-$2 \
      > $OUT/atrium-${build%:*}-$2.log 2>&1
  done ;;
targets-4m)
  for build in $BUILDS; do
    timeout 150 ${build#*:}/manylights bench --sweep docs/bench/nvidia-h100/list-sync/targets-4m/targets-4m.sweep.json \
      --backend egl --out $OUT --name targets-4m-${build%:*} > $OUT/targets-4m-${build%:*}.log 2>&1
  done ;;
headline)
  # The README's results table (--preset scale, atrium-set) but naive, which scans nothing.
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
frames)
  # The scan is integer arithmetic: the change must give main's frames bit for bit.
  F='--size 2560x1440 --lights 1048576 --light-radius overlap:32 --assign exact --brdf ggx --method visibility --vis-raster compute --backend egl'
  for s in atrium:default .corpus-glass/corpus/amd/gas_station/GasStation.gltf:gltf:0; do
    scene=${s%%:*} camera=${s#*:}
    for build in $BUILDS; do
      ${build#*:}/manylights render $F --scene $scene --camera $camera --out /tmp/f.png --out-float /tmp/${build%:*}.pfm \
        > /dev/null 2>> $OUT/frames.txt
    done
    echo "$scene $camera: $(cmp /tmp/main.pfm /tmp/new.pfm && echo identical) $(stat -c %s /tmp/new.pfm) B" >> $OUT/frames.txt
  done ;;
tests)
  # The paths the test binary was built with: the executable beside it.
  mkdir -p /work/main/build && ln -sf $PWD/.devbin-scan/manylights /work/main/build/manylights
  ML_TEST_TMP=/tmp/ml-tests timeout 400 .devbin-scan/ml_gpu_tests \
    --gtest_filter='*PrefixSum*:*Radix*:*Assign*:*Exact*:GlassCapture.*:*Transparen*' 2>&1 \
    | grep -v "^\[ RUN\|^\[--" > $OUT/gpu-tests.txt ;;
accuracy)
  timeout 400 python3 tools/gpu-accuracy --manylights .devbin-scan/manylights --corpus .corpus-glass/corpus \
    --only atrium,GasStation --out $OUT/accuracy > $OUT/accuracy.log 2>&1
  echo "gpu-accuracy exit $?" >> $OUT/accuracy.log
  rm -rf $OUT/accuracy/worst ;;
esac
