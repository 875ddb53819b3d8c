#!/usr/bin/env bash
# Issue 30: the compute raster's edge values from 32-bit differences, each product one 32x32 -> 64-bit
# multiply (glsl/include/compute_raster.glsl, rasterEdges64), against main, on an H200 (nvidia-h200).
# Carry .gl, .corpus-glass (corpus/amd/gas_station alone) and .devbin-we.txz, one archive holding
#   .devbin-main/   before: main at 19b1e6a (the classify-blocks change)
#   .devbin-wide/   the change
#   .devbin-lib/    the libraries tools/pack-for-gpu packs, the same for every build
#   run.sh warm          a few seconds of frames, so that the SM clock has risen before a round
#   run.sh round <n>     targets.sweep.json, every build
#   run.sh frames        the HDR and 8-bit frames of main and $NEW at 1280x720, 4,096 lights, compared
#   run.sh sponza <n>    Sponza's four cameras at 1,048,576 lights (carried as classify-blocks' run.sh says)
#   run.sh targets-4m    4,194,304 lights at 3840x2160, every build
#   run.sh headline      the README's visibility rows: main and $HEADLINE
set -u
[ -d .devbin-lib ] || for a in .devbin-*.txz; do tar xJf $a; done
export LD_LIBRARY_PATH=$PWD/.devbin-lib
S=docs/bench/nvidia-h200/raster-edges
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
BUILDS=${BUILDS:-'main:.devbin-main wide:.devbin-wide'}
NEW=${NEW:-.devbin-wide}
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
  for build in main:.devbin-main ${HEADLINE:-wide:.devbin-wide}; do
    M=${build#*:}/manylights L=${build%:*}
    for n in 1024:1k 65536:64k 1048576:1m; do
      timeout 150 $M bench $P --lights ${n%:*} --out $OUT --name headline-${n#*:}-$L > $OUT/headline-${n#*:}-$L.log 2>&1
      timeout 150 $M bench $P --vis-raster compute --lights ${n%:*} --out $OUT --name compute-${n#*:}-$L > $OUT/compute-${n#*:}-$L.log 2>&1
    done
  done ;;
esac
