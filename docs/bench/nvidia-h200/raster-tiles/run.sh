#!/usr/bin/env bash
# Issue 30: the compute raster's tile pass in 8x8 tiles instead of 16x16 (ML_RASTER_TILE), on an
# H200 (nvidia-h200). Carry .gl, .corpus-glass (corpus/amd/gas_station alone) and the builds:
# .devbin-rt.txz, one archive (the three executables compress to about one) holding
#   .devbin-main/   before: main (903e299's build; 35d6f73 changed only the CPU mirror)
#   .devbin-t8/     ML_RASTER_TILE 8
#   .devbin-t8s32/  ML_RASTER_TILE 8 and ML_RASTER_SMALL_PIXELS 32 (a triangle's own thread up to 32 pixel centres)
#   .devbin-lib/    the libraries tools/pack-for-gpu packs, the same for every build
#   run.sh warm          a few seconds of frames, so that the SM clock has risen before a round
#   run.sh round <n>     targets.sweep.json (the atrium at 65,536 and 1,048,576 lights, the gas station), every build
#   run.sh sponza <n>    sponza.sweep.json: Sponza's four cameras at 1,048,576 lights, every build. Sponza's 14 MB
#                        do not travel beside the tree and the builds: earlier calls carry it in two halves and
#                        copy them to /root/.corpus-sponza (the machine still warm); this step takes it from there.
#   run.sh floors        manylights raster-floors on the atrium's camera set, every build
set -u
[ -d .devbin-lib ] || tar xJf .devbin-rt.txz
export LD_LIBRARY_PATH=$PWD/.devbin-lib
S=docs/bench/nvidia-h200/raster-tiles
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
BUILDS=${BUILDS:-'main:.devbin-main t8:.devbin-t8 t8s32:.devbin-t8s32'}
NEW=${NEW:-.devbin-t8}
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
sponza)
  [ -d .corpus-sponza ] || cp -r /root/.corpus-sponza .
  for build in $BUILDS; do
    timeout 240 ${build#*:}/manylights bench --sweep $S/sponza.sweep.json --backend egl --out $OUT --name sponza-${build%:*}-$2 \
      > $OUT/sponza-${build%:*}-$2.log 2>&1
  done ;;
floors)
  for build in $BUILDS; do
    timeout 120 ${build#*:}/manylights raster-floors --scene atrium --size 2560x1440 --camera atrium-set --backend egl \
      > $OUT/floors-${build%:*}.csv 2> $OUT/floors-${build%:*}.log
  done ;;
esac
