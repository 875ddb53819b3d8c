#!/usr/bin/env bash
# Issue 30: the visibility buffer's lighting with its resolve folded in (glsl/visibility_lighting.comp)
# against main, on an H200 (nvidia-h200). Carry .gl, .corpus-glass (corpus/amd/gas_station alone) and
# .devbin-fu.txz, one archive (the executables compress to about one) holding
#   .devbin-main/   before: main (903e299's build; 35d6f73 changed only the CPU mirror)
#   .devbin-fused/  the change
#   .devbin-lib/    the libraries tools/pack-for-gpu packs, the same for every build
#   run.sh warm          a few seconds of frames, so that the SM clock has risen before a round
#   run.sh round <n>     targets.sweep.json (the atrium at 65,536 lights with both rasters and at
#                        1,048,576, the gas station), main then the change
#   run.sh frames        the HDR frames (PFM) of both builds at 1280x720, 4,096 lights, compared:
#                        the atrium's cameras with both rasters, the gas station's two cameras
set -u
[ -d .devbin-lib ] || tar xJf .devbin-fu.txz
export LD_LIBRARY_PATH=$PWD/.devbin-lib
S=docs/bench/nvidia-h200/visibility-lighting
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
BUILDS=${BUILDS:-'main:.devbin-main fused:.devbin-fused'}
NEW=${NEW:-.devbin-fused}
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
    for build in $BUILDS; do
      ${build#*:}/manylights render --backend egl --method visibility --size 1280x720 --lights 4096 $args \
        --out /tmp/$name-${build%:*}.png --out-float /tmp/$name-${build%:*}.pfm > /dev/null 2>&1 || echo "$name ${build%:*}: render failed"
    done
    echo "$name: $($NEW/manylights compare /tmp/$name-main.pfm /tmp/$name-fused.pfm)"
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
esac
