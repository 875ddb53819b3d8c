#!/usr/bin/env bash
# The glass split by layer over several workgroups a tile (the first commit of branch glass-layers on main at 747f713;
# glass-layers): the gas station before and with ML_GLASS_LAYERS=1..4, twice, and the atrium at
# 1,048,576 lights before and with 2, in one command. Carry .gl, .devbin.txz (that build),
# .devbin-old.txz (747f713) and .corpus-gas.
set -u
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
S=docs/bench/nvidia-h100/cooperative-rounds/gas.sweep.json
timeout 60 .devbin/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --warmup 5 --timed-frames 300 --backend egl --out $OUT/warm --name warm > /dev/null 2>&1; rm -rf $OUT/warm
for n in 1 2; do
  timeout 120 .devbin-old/manylights bench --sweep $S --backend egl --out $OUT --name gas-old-$n > $OUT/gas-old-$n.log 2>&1
  for L in 1 2 3 4; do
    ML_GLASS_LAYERS=$L timeout 120 .devbin/manylights bench --sweep $S --backend egl --out $OUT --name gas-L$L-$n > $OUT/gas-L$L-$n.log 2>&1
  done
done
# the atrium's glass at 1M lights, old and L=2
timeout 200 .devbin-old/manylights bench --scene atrium --camera atrium-set --lights 1048576 --light-radius overlap:32 --size 2560x1440 --method visibility --vis-raster compute --warmup 5 --timed-frames 30 --backend egl --out $OUT --name atrium-old > $OUT/atrium-old.log 2>&1
ML_GLASS_LAYERS=2 timeout 200 .devbin/manylights bench --scene atrium --camera atrium-set --lights 1048576 --light-radius overlap:32 --size 2560x1440 --method visibility --vis-raster compute --warmup 5 --timed-frames 30 --backend egl --out $OUT --name atrium-L2 > $OUT/atrium-L2.log 2>&1
cd $OUT && tar czf all.tgz --exclude=all.tgz * && find . -mindepth 1 -not -name all.tgz -delete
