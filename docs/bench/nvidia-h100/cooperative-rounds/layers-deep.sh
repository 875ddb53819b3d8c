#!/usr/bin/env bash
# The glass split by layer over several workgroups, for the tiles that need it alone (layers.patch, branch
# glass-layers): the gas station and the atrium at 1,048,576 lights before and with
# ML_GLASS_LAYERS=n, ML_GLASS_DEEP=d (tiles with a pixel of d fragments or more split in n), twice,
# in one command. Carry .gl, .devbin.txz (that build), .devbin-old.txz (747f713) and .corpus-gas.
set -u
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
S=docs/bench/nvidia-h100/cooperative-rounds/gas.sweep.json
A="--scene atrium --camera atrium-set --lights 1048576 --light-radius overlap:32 --size 2560x1440 --method visibility --vis-raster compute --warmup 5 --timed-frames 30 --backend egl"
timeout 60 .devbin/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --warmup 5 --timed-frames 300 --backend egl --out $OUT/warm --name warm > /dev/null 2>&1; rm -rf $OUT/warm
for n in 1 2; do
  timeout 120 .devbin-old/manylights bench --sweep $S --backend egl --out $OUT --name gas-old-$n > $OUT/gas-old-$n.log 2>&1
  timeout 120 .devbin-old/manylights bench $A --out $OUT --name atrium-old-$n > $OUT/atrium-old-$n.log 2>&1
  for v in 4:2 4:3 2:2; do
    ML_GLASS_LAYERS=${v%:*} ML_GLASS_DEEP=${v#*:} timeout 120 .devbin/manylights bench --sweep $S --backend egl --out $OUT --name gas-L${v%:*}d${v#*:}-$n > $OUT/gas-L${v%:*}d${v#*:}-$n.log 2>&1
    ML_GLASS_LAYERS=${v%:*} ML_GLASS_DEEP=${v#*:} timeout 120 .devbin/manylights bench $A --out $OUT --name atrium-L${v%:*}d${v#*:}-$n > $OUT/atrium-L${v%:*}d${v#*:}-$n.log 2>&1
  done
done
cd $OUT && tar czf all.tgz --exclude=all.tgz * && find . -mindepth 1 -not -name all.tgz -delete
