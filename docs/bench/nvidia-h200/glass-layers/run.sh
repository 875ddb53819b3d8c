#!/usr/bin/env bash
# Issue 30: the glass's deep tiles split over several workgroups (glsl/glass_shade.comp), on an
# H200 (nvidia-h200; no H100 was lent that session). Carry .gl, .corpus-glass
# (corpus/amd/gas_station and corpus/khronos's AlphaBlendModeTest and LightsPunctualLamp: the
# files with BLEND materials) and the builds, each packed by tools/pack-for-gpu as
# .devbin<suffix>.txz:
#   .devbin      the change (manylights, ml_gpu_tests)
#   .devbin-old  main before it (82468bf; its manylights alone, run with .devbin's libraries)
#   .devbin-var  the change with variants.patch: ML_GLASS_LAYERS (parts a deep tile at most) and
#                ML_GLASS_DEEP (fragments a pixel needs for its tile to split) read at start
#   run.sh warm          a few seconds of frames, so that the SM clock has risen before a round
#   run.sh round <n>     gas.sweep.json and atrium.sweep.json, main before it then the change
#   run.sh variants <n>  the same sweeps through .devbin-var, at 1 (no split), 2, 4 (the default)
#                        and 8 parts from two fragments, and 4 parts from three
#   run.sh targets-4m    4,194,304 lights at 3840x2160 (list-sync's sweep), before and after
#   run.sh headline      the README's results table (--preset scale, atrium-set) but naive, which
#                        splits nothing: main before it, then the change
#   run.sh tests         the glass's GPU tests (the split against one pass, bit for bit)
#   run.sh accuracy      tools/gpu-accuracy on the scenes with glass: every method and layout against naive
set -u
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
D=docs/bench/nvidia-h200/glass-layers
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
label() { local l=${1:--new}; echo ${l#-}; }
sweeps() {  # <binary> <name suffix>
  for s in gas atrium; do
    timeout 200 $1 bench --sweep $D/$s.sweep.json --backend egl --out $OUT --name $s-$2 > $OUT/$s-$2.log 2>&1
  done
}
case "$1" in
warm)
  timeout 60 .devbin/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --warmup 5 --timed-frames 300 \
    --backend egl --out $OUT/warm --name warm > /dev/null 2>&1
  rm -rf $OUT/warm ;;
round)
  for build in -old ""; do sweeps .devbin$build/manylights $(label $build)-$2; done ;;
variants)
  for v in 1:2 2:2 4:2 8:2 4:3; do
    ML_GLASS_LAYERS=${v%:*} ML_GLASS_DEEP=${v#*:} sweeps .devbin-var/manylights ${v%:*}d${v#*:}-$2
  done ;;
targets-4m)
  for build in -old ""; do
    timeout 120 .devbin$build/manylights bench --sweep docs/bench/nvidia-h100/list-sync/targets-4m/targets-4m.sweep.json \
      --backend egl --out $OUT --name targets-4m-$(label $build) > $OUT/targets-4m-$(label $build).log 2>&1
  done ;;
headline)
  S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
  for build in -old ""; do
    M=.devbin$build/manylights L=$(label $build)
    $M bench $S --method forward-plus,deferred,visibility --lights 1024 --out $OUT --name headline-1k-$L > $OUT/headline-1k-$L.log 2>&1
    $M bench $S --method forward-plus,deferred,visibility --lights 65536 --out $OUT --name headline-64k-$L > $OUT/headline-64k-$L.log 2>&1
    $M bench $S --method deferred,visibility --lights 1048576 --out $OUT --name headline-1m-$L > $OUT/headline-1m-$L.log 2>&1
    for n in 1024:1k 65536:64k 1048576:1m; do
      $M bench $S --method visibility --vis-raster compute --lights ${n%:*} --out $OUT --name compute-${n#*:}-$L > $OUT/compute-${n#*:}-$L.log 2>&1
    done
  done ;;
tests)
  # The paths the test binary was built with: the executable beside it.
  mkdir -p /work/main/build-test && ln -sf $PWD/.devbin/manylights /work/main/build-test/manylights
  ML_TEST_TMP=/tmp/ml-tests timeout 400 .devbin/ml_gpu_tests --gtest_filter='GlassCapture.*:*Transparen*' 2>&1 \
    | grep -v "^\[ RUN\|^\[--" > $OUT/gpu-tests.txt ;;
accuracy)
  timeout 400 python3 tools/gpu-accuracy --manylights .devbin/manylights --corpus .corpus-glass/corpus \
    --only atrium,GasStation,AlphaBlendModeTest,LightsPunctualLamp --out $OUT/accuracy > $OUT/accuracy.log 2>&1
  echo "gpu-accuracy exit $?" >> $OUT/accuracy.log
  rm -rf $OUT/accuracy/worst ;;
esac
