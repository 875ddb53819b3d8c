#!/usr/bin/env bash
# Issue 30's targets at its end, before and after on one machine (nvidia-h100-x1). Before: main at
# bbdf756, where the issue's figures were taken (.devbin-old/); after: main at the issue's end
# (.devbin-new/, --vis-raster hardware, its default, and compute). All in one archive,
# .devbin-final.txz, with .devbin-lib/ (tools/pack-for-gpu's libraries; stripped manylights and
# ml_gpu_tests in each folder); carry it with .gl, .corpus-glass (corpus/amd/gas_station) and
# Sponza's four parts (.sponza-part0..3: corpus/amd/sponza).
#   run.sh targets LABEL   a minute of frames to raise the SM clock, then targets-old.sweep.json
#                          and targets-new.sweep.json, and `raster-floors` with the compute raster
#   run.sh headline        the README's results table on main: --preset scale on atrium-set,
#                          every method, the visibility buffer by both rasters (BUILD=fix: the
#                          build in .devbin-fix/, main after naive's bands were mended)
#   run.sh rerun           rerun.sweep.json: the points both runs read below 1980 MHz
#   run.sh floors          `raster-floors` on Sponza's four cameras and the gas station's two
#   run.sh tests           ml_gpu_tests on this GPU, with main's `auto` raster and with the compute
#                          raster as `auto` (.devbin-cdef/); TEST_BUILDS and TESTS (a gtest
#                          filter) choose others
# Every file lands in $OUT/LABEL.tgz (the device tool returns few files).
set -u
D=docs/bench/nvidia-h100/issue-30-final
STEP=$1
LABEL=${2:-$1}
FINAL=$OUT
OUT=/tmp/results/$LABEL
mkdir -p $OUT
[ -d .devbin-lib ] || tar xJf .devbin-final.txz
export LD_LIBRARY_PATH=$PWD/.devbin-lib
if [ ! -d .corpus-sponza ] && [ -f .sponza-part0 ]; then
  mkdir -p .corpus-sponza && cat .sponza-part0 .sponza-part1 .sponza-part2 .sponza-part3 | tar x -C .corpus-sponza
fi
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
pack() { tar czf $FINAL/$LABEL.tgz -C /tmp/results $LABEL; }
case "$STEP" in
targets)
  # The targets' settings: the bench's default radius would need lists past the GPU's largest
  # storage block at a million lights.
  timeout 60 .devbin-new/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --light-radius overlap:32 \
    --method visibility --warmup 5 --timed-frames 600 --backend egl --out /tmp/warm --name warm > $OUT/warm.log 2>&1
  for build in old new; do
    timeout 240 .devbin-$build/manylights bench --sweep $D/targets-$build.sweep.json --backend egl --out $OUT \
      --name targets-$build > $OUT/targets-$build.log 2>&1
    pack
  done
  timeout 60 .devbin-new/manylights raster-floors --scene atrium --camera atrium-set --size 2560x1440 --backend egl \
    --csv $OUT/raster-floors.csv > $OUT/floors.log 2>&1 ;;
headline)
  P='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
  M=.devbin-${BUILD:-new}/manylights
  timeout 150 $M bench $P --method naive,forward-plus,deferred,visibility --lights 1024 --out $OUT --name headline-1k > $OUT/headline-1k.log 2>&1
  timeout 100 $M bench $P --method forward-plus,deferred,visibility --lights 65536 --out $OUT --name headline-64k > $OUT/headline-64k.log 2>&1
  timeout 100 $M bench $P --method deferred,visibility --lights 1048576 --out $OUT --name headline-1m > $OUT/headline-1m.log 2>&1
  pack
  for n in 1024:1k 65536:64k 1048576:1m; do
    timeout 100 $M bench $P --method visibility --vis-raster compute --lights ${n%:*} --out $OUT --name compute-${n#*:} \
      > $OUT/compute-${n#*:}.log 2>&1
  done ;;
rerun)
  # The points that read below 1980 MHz in targets-a and targets-b, after a minute at 4K.
  timeout 60 .devbin-new/manylights bench --scene atrium --lights 4194304 --size 3840x2160 --light-radius overlap:32 \
    --method visibility --vis-raster compute --warmup 5 --timed-frames 3000 --backend egl --out /tmp/warm --name warm > $OUT/warm.log 2>&1
  timeout 200 .devbin-new/manylights bench --sweep $D/rerun.sweep.json --backend egl --out $OUT --name rerun > $OUT/rerun.log 2>&1 ;;
floors)
  # The same floors on the two AMD files: their hardware raster's floor bounds their frames.
  for file in .corpus-sponza/corpus/amd/sponza/Sponza.gltf:'gltf:0;gltf:1;gltf:2;gltf:3' \
              .corpus-glass/corpus/amd/gas_station/GasStation.gltf:'gltf:0;gltf:1'; do
    name=$(basename ${file%%:*} .gltf)
    timeout 90 .devbin-new/manylights raster-floors --scene ${file%%:*} --camera "${file#*:}" --size 2560x1440 \
      --backend egl --csv $OUT/raster-floors-$name.csv > $OUT/floors-$name.log 2>&1
  done ;;
tests)
  # The paths ml_gpu_tests was built with: the tree at /work/main, its executable in build/, the
  # corpus in /work/shared/corpus (here AMD's two files only: the tests of other files fail for
  # want of them). Once with main's `auto` raster (the hardware), once with a build whose `auto`
  # is the compute raster (.devbin-cdef/: main but for that line).
  [ "$PWD" = /work/main ] || { mkdir -p /work && ln -sfn $PWD /work/main; }
  mkdir -p build /work/shared/corpus/amd /tmp/ml-tests
  ln -sfn $PWD/.corpus-sponza/corpus/amd/sponza /work/shared/corpus/amd/sponza
  ln -sfn $PWD/.corpus-glass/corpus/amd/gas_station /work/shared/corpus/amd/gas_station
  for build in ${TEST_BUILDS:-new cdef}; do
    ln -sf $PWD/.devbin-$build/manylights build/manylights
    ML_TEST_TMP=/tmp/ml-tests timeout 250 .devbin-$build/ml_gpu_tests --gtest_filter="${TESTS:-*}" 2>&1 | grep -v '^\[ RUN\|^\[--' > $OUT/ml_gpu_tests-$build.txt
    echo "ml_gpu_tests exit ${PIPESTATUS[0]}" >> $OUT/ml_gpu_tests-$build.txt
    pack
  done ;;
*)
  echo "run.sh: unknown step '$STEP' (targets LABEL, headline, rerun, floors, tests)" >&2
  exit 2 ;;
esac
pack
