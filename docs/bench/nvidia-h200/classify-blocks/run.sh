#!/usr/bin/env bash
# Issue 30: passes that wait on memory given several pixels an invocation, against main, on an
# H200 (nvidia-h200). Carry .gl, .corpus-glass (corpus/amd/gas_station alone) and .devbin-cb.txz,
# one archive (the executables compress to about one) holding
#   .devbin-main/   before: main (903e299's build; 35d6f73 changed only the CPU mirror)
#   .devbin-b2/     the resolve's tile classification (glsl/visibility_classify.comp): 2x2 pixels
#                   an invocation, 2x2 tiles a workgroup (kClassifyBlock 2)
#   .devbin-x2/     b2, and 2 pixels an invocation in the resolve (kResolvePixels), the compute
#                   raster's finish (kFinishPixels) and the tonemap (kTonemapPixels)
#   .devbin-x4/     x2 with 4 pixels an invocation in the finish and the tonemap
#   (part 1 ran b4 instead of x2 and x4: 4x4 pixels an invocation in the classification, 4x4 tiles
#   a workgroup; BUILDS='main:.devbin-main b2:.devbin-b2 b4:.devbin-b4')
#   .devbin-lib/    the libraries tools/pack-for-gpu packs, the same for every build
#   run.sh warm          a few seconds of frames, so that the SM clock has risen before a round
#   run.sh round <n>     targets.sweep.json (the atrium at 65,536 lights with both rasters and at
#                        1,048,576, the gas station), every build
#   run.sh frames        the HDR frames (PFM) and the 8-bit ones of main and $NEW at 1280x720, 4,096
#                        lights, compared: the atrium's cameras with both rasters, the gas station's two
#   run.sh sponza <n>    Sponza's four cameras at 1,048,576 lights, compute raster (raster-tiles' sweep), every build
#   run.sh targets-4m    4,194,304 lights at 3840x2160 (list-sync's sweep), every build
#   run.sh headline      the README's results table's visibility rows (both rasters; the other rows run
#                        none of this code): main and $HEADLINE
set -u
[ -d .devbin-lib ] || for a in .devbin-*.txz; do tar xJf $a; done
export LD_LIBRARY_PATH=$PWD/.devbin-lib
S=docs/bench/nvidia-h200/classify-blocks
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
BUILDS=${BUILDS:-'main:.devbin-main b2:.devbin-b2 x2:.devbin-x2 x4:.devbin-x4'}
NEW=${NEW:-.devbin-x2}
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
frames)
  G=.corpus-glass/corpus/amd/gas_station/GasStation.gltf
  while read -r name args; do
    for build in main:.devbin-main new:$NEW; do
      ${build#*:}/manylights render --backend egl --method visibility --size 1280x720 --lights 4096 $args \
        --out /tmp/$name-${build%:*}.png --out-float /tmp/$name-${build%:*}.pfm > /dev/null 2>&1 || echo "$name ${build%:*}: render failed"
    done
    echo "$name: $($NEW/manylights compare /tmp/$name-main.pfm /tmp/$name-new.pfm); 8-bit: $($NEW/manylights compare /tmp/$name-main.png /tmp/$name-new.png)"
  done > $OUT/frames.txt <<LIST
atrium-default --scene atrium
atrium-gallery --scene atrium --camera -15,1.7,-6.3,15,1.7,-6.3,60
atrium-roof --scene atrium --camera 0,28,0.5,0,0,0,60
atrium-corner --scene atrium --camera -16,3,-4.5,16,1.5,4.5,60
atrium-default-compute --scene atrium --vis-raster compute
atrium-roof-compute --scene atrium --vis-raster compute --camera 0,28,0.5,0,0,0,60
gas-0 --scene $G --camera gltf:0
gas-1 --scene $G --camera gltf:1
LIST
  ;;
sponza)
  # Sponza's 14 MB do not travel beside the tree and the builds: two earlier calls carry it in two
  # halves into /root/.corpus-sponza (the machine still warm); this step takes it from there.
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
  for build in main:.devbin-main ${HEADLINE:-x2:.devbin-x2}; do
    M=${build#*:}/manylights L=${build%:*}
    for n in 1024:1k 65536:64k 1048576:1m; do
      timeout 150 $M bench $P --lights ${n%:*} --out $OUT --name headline-${n#*:}-$L > $OUT/headline-${n#*:}-$L.log 2>&1
      timeout 150 $M bench $P --vis-raster compute --lights ${n%:*} --out $OUT --name compute-${n#*:}-$L > $OUT/compute-${n#*:}-$L.log 2>&1
    done
  done ;;
esac
