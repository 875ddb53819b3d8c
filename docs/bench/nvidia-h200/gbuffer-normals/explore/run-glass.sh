#!/usr/bin/env bash
# Exploring call (explore/README.md): builds in .devbin-x.txz (.devbin-ncull: 789d0b1; .devbin-hoist:
# ef61a13; .devbin-noglass: ef61a13 with ML_LIST_ROUNDS_NORMAL_BOUND 0 in glsl/glass_shade.comp),
# with .gl and the corpus as .corpus/corpus; rounds $1.. (ran as .exp/glass.sh 1 2, the sweep in .exp/).
set -u
export LD_LIBRARY_PATH=$PWD/.devbin-lib
timeout 60 .devbin-hoist/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --light-radius overlap:32 \
  --method visibility --vis-raster compute --warmup 5 --timed-frames 2000 --backend egl --out /tmp/warm --name warm > $OUT/warm.log 2>&1
for round in "$@"; do
  for b in ncull hoist noglass; do
    timeout 150 .devbin-$b/manylights bench --sweep docs/bench/nvidia-h200/gbuffer-normals/explore/glass.sweep.json --backend egl --out $OUT --name g-$b-$round > $OUT/g-$b-$round.log 2>&1
  done
  rm -f $OUT/*.json; tar czf $REAL/res.tgz -C $OUT .
done
