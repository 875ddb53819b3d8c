#!/usr/bin/env bash
# Issue 30: alpha-tested triangles in the compute raster, on the H100 (nvidia-h100-x1). Carry .gl,
# .corpus-sponza, and the builds, each packed as .devbin<suffix>.txz
# (tools/pack-for-gpu; besides .devbin, the manylights binary alone, run with .devbin's libraries):
#   .devbin          the change (manylights, ml_gpu_tests, ml_corpus_tests): the overlap below,
#                    and triangles past the guard band rastered as homogeneous planes
#   .devbin-overlap  each step of the alpha-tested triangles dispatched right after the opaque
#                    ones' same step (rounds 2-7)
#   .devbin-seq      the change's first form (f8e7cda): the alpha-tested triangles' steps after
#                    the opaque triangles' whole raster, behind barriers of their own (rounds 1-4)
#   .devbin-old      main before it (9a5f1ac): alpha-tested ranges drawn by the hardware into the store
#   .devbin-s128, .devbin-s256  the change with ML_RASTER_SMALL_PIXELS 128 and 256 instead of 64
#                    (small-pixels.patch, shown at 256; rounds 8-9: round <n> "" -s128 -s256)
#   run.sh warm                   a few seconds of frames, so that the SM clock has risen before a round
#   run.sh round <n> <suffix>...  targets.sweep.json with each build in turn ("" is .devbin),
#                                 named targets-<suffix, or new>-<n>
#   run.sh stats       --stats of one frame per scene and build: where the triangles went
#   run.sh headline    the README's results table's compute-raster row
#   run.sh gas         the gas station's two cameras, before and after, twice (carry .corpus-gas)
#   run.sh floors      raster-floors before and after, the atrium's and Sponza's cameras
#   run.sh targets-4m  4,194,304 lights at 3840x2160 (list-sync's sweep), before and after, twice
#   run.sh tests       every GPU test (gpu-tests.txt), and the corpus's compute-raster ids on Sponza
set -u
D=docs/bench/nvidia-h100/alpha-raster
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
case "$1" in
warm)
  timeout 60 .devbin/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --warmup 5 --timed-frames 300 \
    --backend egl --out $OUT/warm --name warm > /dev/null 2>&1
  rm -rf $OUT/warm ;;
round)
  n=$2; shift 2
  for build in "$@"; do
    label=${build:--new}; label=${label#-}
    timeout 280 .devbin$build/manylights bench --sweep $D/targets.sweep.json --backend egl --out $OUT --name targets-$label-$n \
      > $OUT/targets-$label-$n.log 2>&1
  done ;;
gas)
  # gas.sweep.json with each build in turn, twice (carry .corpus-gas instead of .corpus-sponza)
  for n in 1 2; do
    for build in -old ""; do
      label=${build:--new}; label=${label#-}
      timeout 120 .devbin$build/manylights bench --sweep $D/gas.sweep.json --backend egl --out $OUT --name gas-$label-$n \
        > $OUT/gas-$label-$n.log 2>&1
    done
  done
  .devbin/manylights render --scene .corpus-gas/corpus/amd/gas_station/GasStation.gltf --camera gltf:0 --method visibility \
    --vis-raster compute --lights 65536 --size 2560x1440 --stats --backend egl --out $OUT/stats.png 2>&1 | grep -i "raster" > $OUT/stats-gas.txt
  rm -f $OUT/stats.png ;;
targets-4m)
  # issue 30's 4M target (list-sync's sweep), each build in turn, twice
  for n in 1 2; do
    for build in -old ""; do
      label=${build:--new}; label=${label#-}
      timeout 120 .devbin$build/manylights bench --sweep docs/bench/nvidia-h100/list-sync/targets-4m/targets-4m.sweep.json \
        --backend egl --out $OUT --name targets-4m-$label-$n > $OUT/targets-4m-$label-$n.log 2>&1
    done
  done ;;
floors)
  # raster-floors (the raster's probes, the compute raster and its steps) before and after: the
  # atrium's camera set and Sponza's cameras at 2560x1440
  for build in -old ""; do
    label=${build:--new}; label=${label#-}
    .devbin$build/manylights raster-floors --scene atrium --camera atrium-set --size 2560x1440 --backend egl \
      --csv $OUT/floors-atrium-$label.csv > /dev/null 2>&1
    .devbin$build/manylights raster-floors --scene .corpus-sponza/corpus/amd/sponza/Sponza.gltf --camera 'gltf:0;gltf:1;gltf:2;gltf:3' \
      --size 2560x1440 --backend egl --csv $OUT/floors-sponza-$label.csv > /dev/null 2>&1
  done ;;
stats)
  for build in -old ""; do
    label=${build:--new}; label=${label#-}
    for s in .corpus-sponza/corpus/amd/sponza/Sponza.gltf atrium; do
      .devbin$build/manylights render --scene $s --method visibility --vis-raster compute --lights 65536 --size 2560x1440 \
        --stats --backend egl --out $OUT/stats.png 2>&1 | grep -i "raster\|scene" >> $OUT/stats-$label.txt
    done
  done
  rm -f $OUT/stats.png ;;
headline)
  # The README's results table's compute-raster row (--preset scale, atrium-set); the other rows
  # run nothing this change touches.
  S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
  for n in 1024:1k 65536:64k 1048576:1m; do
    .devbin/manylights bench $S --method visibility --vis-raster compute --lights ${n%:*} --out $OUT --name compute-${n#*:} \
      > $OUT/compute-${n#*:}.log 2>&1
  done ;;
tests)
  mkdir -p /work/main/build-test /work/shared
  ln -sf $PWD/.devbin/manylights /work/main/build-test/manylights
  ln -sfn $PWD/.corpus-sponza/corpus /work/shared/corpus
  timeout 400 .devbin/ml_gpu_tests 2>&1 | grep -v "^\[ RUN\|^\[--" > $OUT/gpu-tests.txt
  timeout 150 .devbin/ml_corpus_tests --gtest_filter='*ComputeRasterGivesTheHardwareIds/Sponza_gltf' 2>&1 | tail -40 > $OUT/corpus-compute-raster.txt ;;
esac
