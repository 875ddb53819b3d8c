#!/usr/bin/env bash
# Not kept: a tile splits only where a pixel of two fragments or more has fragments whose lists
# hold, summed, at least W lights (ML_GLASS_DEEP_WORK=W; 0: the depth rule alone, as on main).
# .devbin-work: the change with work-rule.patch (which holds variants.patch's lines too; its
# manylights alone, run with .devbin's libraries). Carry as run.sh says, with .devbin-work.txz.
#   work-rule.sh <run>   gas.sweep.json and atrium.sweep.json at each W
set -u
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
D=docs/bench/nvidia-h200/glass-layers
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
for w in 0 1024 4096 16384; do
  for s in gas atrium; do
    ML_GLASS_DEEP_WORK=$w timeout 200 .devbin-work/manylights bench --sweep $D/$s.sweep.json --backend egl --out $OUT \
      --name $s-w$w-$1 > $OUT/$s-w$w-$1.log 2>&1
  done
done
