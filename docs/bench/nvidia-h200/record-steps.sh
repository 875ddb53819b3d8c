#!/usr/bin/env bash
# The steps an H200 record's run.sh runs (sourced, after it sets the variables below), so that
# each record names only what it measures. Builds come in one archive, .devbin-<name>.txz, holding
# .devbin-<build>/ (stripped executables) and .devbin-lib/ (the libraries tools/pack-for-gpu
# packs, the same for every build); carry it with .gl and .corpus-glass (corpus/amd/gas_station).
#   S          the record's folder (its targets.sweep.json)
#   BUILDS     'label:folder ...', every build a round runs; the first is the baseline
#   NEW        the build the frames step compares with the first
#   HEADLINE   'label:folder' of the build the headline step runs beside the first
#   TESTS      the tests step's gtest filter
# Steps:
#   warm          a minute of frames, so that the SM clock has risen before a round
#   round <n>     $S/targets.sweep.json, every build
#   frames        the HDR and 8-bit frames of the first build and $NEW at 1280x720, 4,096 lights
#                 (the atrium's four cameras and the gas station's two, both rasters)
#   sponza <n>    Sponza's four cameras at 1,048,576 lights, every build (Sponza's 14 MB do not
#                 travel beside the tree and the builds: earlier calls carry it in parts
#                 into /root/.corpus-sponza/corpus/amd/sponza while the machine stays warm)
#   targets-4m    4,194,304 lights at 3840x2160, every build
#   headline      the README's visibility rows, both rasters: the first build and $HEADLINE
#   tests         the GPU tests $TESTS of .devbin-tests/ml_gpu_tests (stripped) on this GPU
#   sequence      four frames of an orbit, scene and renderer built once, of the atrium, Sponza and
#                 the gas station with the compute raster (its store alternates its order frame to
#                 frame): every frame of the first build and $NEW at 1280x720, 4,096 lights
set -u
[ -d .devbin-lib ] || for a in .devbin-*.txz; do tar xJf $a; done
export LD_LIBRARY_PATH=$PWD/.devbin-lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
BASE=${BUILDS%% *}
case "$1" in
warm)
  # The targets' settings: the bench's default radius would need lists past the GPU's largest
  # storage block at a million lights, and the step would end at once (records before
  # gbuffer-normals ran so: their warm step warmed nothing).
  timeout 60 ${NEW}/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --light-radius overlap:32 \
    --method visibility --vis-raster compute --warmup 5 --timed-frames 600 --backend egl --out $OUT/warm --name warm \
    > $OUT/warm.log 2>&1
  rm -rf $OUT/warm ;;
round)
  for build in $BUILDS; do
    timeout 240 ${build#*:}/manylights bench --sweep $S/targets.sweep.json --backend egl --out $OUT --name targets-${build%:*}-$2 \
      > $OUT/targets-${build%:*}-$2.log 2>&1
  done ;;
frames)
  G=.corpus-glass/corpus/amd/gas_station/GasStation.gltf
  while read -r name args; do
    for build in base:${BASE#*:} new:$NEW; do
      ${build#*:}/manylights render --backend egl --method visibility --size 1280x720 --lights 4096 $args \
        --out /tmp/$name-${build%:*}.png --out-float /tmp/$name-${build%:*}.pfm > /dev/null 2>&1 || echo "$name ${build%:*}: render failed"
    done
    echo "$name: $($NEW/manylights compare /tmp/$name-base.pfm /tmp/$name-new.pfm); 8-bit: $($NEW/manylights compare /tmp/$name-base.png /tmp/$name-new.png)"
  done > $OUT/frames.txt <<LIST
atrium-default --scene atrium
atrium-gallery --scene atrium --camera -15,1.7,-6.3,15,1.7,-6.3,60
atrium-roof --scene atrium --camera 0,28,0.5,0,0,0,60
atrium-corner --scene atrium --camera -16,3,-4.5,16,1.5,4.5,60
atrium-default-compute --scene atrium --vis-raster compute
atrium-roof-compute --scene atrium --vis-raster compute --camera 0,28,0.5,0,0,0,60
atrium-gallery-compute --scene atrium --vis-raster compute --camera -15,1.7,-6.3,15,1.7,-6.3,60
atrium-corner-compute --scene atrium --vis-raster compute --camera -16,3,-4.5,16,1.5,4.5,60
gas-0 --scene $G --camera gltf:0
gas-1 --scene $G --camera gltf:1
gas-0-compute --scene $G --vis-raster compute --camera gltf:0
gas-1-compute --scene $G --vis-raster compute --camera gltf:1
LIST
  ;;
sponza)
  # Sponza travels in four parts (.sponza-part0..3) in one call and stays while the machine does.
  if [ ! -d /root/.corpus-sponza ] && [ -f .sponza-part0 ]; then
    mkdir -p /root/.corpus-sponza && cat .sponza-part0 .sponza-part1 .sponza-part2 .sponza-part3 | tar x -C /root/.corpus-sponza
  fi
  [ -d .corpus-sponza ] || cp -r /root/.corpus-sponza .
  for build in $BUILDS; do
    timeout 240 ${build#*:}/manylights bench --sweep docs/bench/nvidia-h200/raster-tiles/sponza.sweep.json --backend egl \
      --out $OUT --name sponza-${build%:*}-$2 > $OUT/sponza-${build%:*}-$2.log 2>&1
  done ;;
targets-4m)
  for build in $BUILDS; do
    timeout 150 ${build#*:}/manylights bench --sweep docs/bench/nvidia-h100/list-sync/targets-4m/targets-4m.sweep.json \
      --backend egl --out $OUT --name targets-4m-${build%:*} > $OUT/targets-4m-${build%:*}.log 2>&1
  done ;;
headline)
  P='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl --method visibility'
  for build in base:${BASE#*:} $HEADLINE; do
    M=${build#*:}/manylights L=${build%:*}
    for n in 1024:1k 65536:64k 1048576:1m; do
      timeout 150 $M bench $P --lights ${n%:*} --out $OUT --name headline-${n#*:}-$L > $OUT/headline-${n#*:}-$L.log 2>&1
      timeout 150 $M bench $P --vis-raster compute --lights ${n%:*} --out $OUT --name compute-${n#*:}-$L > $OUT/compute-${n#*:}-$L.log 2>&1
    done
  done ;;
sequence)
  G=.corpus-glass/corpus/amd/gas_station/GasStation.gltf
  if [ ! -d /root/.corpus-sponza ] && [ -f .sponza-part0 ]; then
    mkdir -p /root/.corpus-sponza && cat .sponza-part0 .sponza-part1 .sponza-part2 .sponza-part3 | tar x -C /root/.corpus-sponza
  fi
  while read -r name scene; do
    for build in base:${BASE#*:} new:$NEW; do
      ${build#*:}/manylights render --backend egl --method visibility --vis-raster compute --size 1280x720 --lights 4096 \
        --scene $scene --camera orbit:frames=8 --frames 0..3 --out /tmp/$name-%d-${build%:*}.png \
        --out-float /tmp/$name-%d-${build%:*}.pfm > /dev/null 2>&1 || echo "$name ${build%:*}: render failed"
    done
    for k in 0 1 2 3; do
      echo "$name frame $k: $($NEW/manylights compare /tmp/$name-$k-base.pfm /tmp/$name-$k-new.pfm)"
    done
  done > $OUT/sequence.txt <<LIST
atrium atrium
sponza /root/.corpus-sponza/corpus/amd/sponza/Sponza.gltf
gas $G
LIST
  cp /tmp/sponza-1-new.png /tmp/atrium-3-new.png $OUT/ 2>/dev/null ;;
tests)
  mkdir -p /tmp/ml-tests; ML_TEST_TMP=/tmp/ml-tests timeout 300 .devbin-tests/ml_gpu_tests --gtest_filter="$TESTS" > $OUT/tests.log 2>&1
  echo "ml_gpu_tests exit $?" >> $OUT/tests.log ;;
*)
  echo "record-steps.sh: unknown step '$1' (warm, round N, frames, sponza N, targets-4m, headline, tests, sequence)" >&2
  exit 2 ;;
esac
