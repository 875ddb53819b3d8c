#!/usr/bin/env bash
# Where the lighting pass's time goes (issue 30): one binary with scratch.patch (split/), whose
# variants the environment chooses, on one machine (nvidia-h100-x1) in one command: the pass
# as it is; with every staged light's shading replaced by a trivial add (staging, culling and
# the loop); with every list empty (the rounds' barriers and the surface, no light); with no
# round at all (the surface and the frame write). Carry .devbin.txz, .gl and .corpus-f.
# Everything lands in $OUT/split.tgz.
set -u
D=docs/bench/nvidia-h100/lighting-tiles
FINAL=$OUT
OUT=/tmp/results/split
mkdir -p $OUT
[ -d .devbin ] || tar xJf .devbin.txz
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
M="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
for pass in a b; do
  for v in full ML_SCRATCH_SHADE_ZERO ML_SCRATCH_NO_LIST ML_SCRATCH_NO_ROUNDS; do
    e=""; [ $v = full ] || e="$v=1"
    env $e $M bench --sweep $D/lighting.sweep.json --backend egl --out $OUT --name $v-$pass > $OUT/$v-$pass.log 2>&1
  done
done
tar czf $FINAL/split.tgz -C /tmp/results split
