#!/usr/bin/env bash
# The lighting pass in blocks of 16x16 pixels culled by 8x8 boxes (issue 30), before and after
# on one machine (nvidia-h100-x1) in one command. Before: main at a7d6589 (.devbin-old); after:
# the blocks (.devbin built with blocks/blocks.patch, with ml_gpu_tests), whose block side ML_SCRATCH_LIGHTING_TILE may set
# (8, 16, 24) for this record. Carry .devbin.txz, .devbin-old.txz, .gl and .corpus-f.
# Everything lands in $OUT/lighting.tgz.
set -u
D=docs/bench/nvidia-h100/lighting-tiles
FINAL=$OUT
OUT=/tmp/results/lighting
mkdir -p $OUT
for b in .devbin .devbin-old; do [ -d $b ] || tar xJf $b.txz; done
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
OLD="env LD_LIBRARY_PATH=.devbin-old/lib .devbin-old/manylights"
NEW="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
# Frames: each point's sum runs over the same lights in the same order, so every frame must be
# the old binary's bit for bit (float output).
frame() {  # label binary-var tile args...
  local label=$1 bin=$2 tile=$3; shift 3
  env ML_SCRATCH_LIGHTING_TILE=$tile ${!bin} render "$@" --backend egl --out-float /tmp/$label.pfm --out /tmp/$label.png > /dev/null 2>&1
  md5sum < /tmp/$label.pfm | cut -c1-32
}
{
  for scene in "--scene .corpus-f/amd/sponza/Sponza.gltf --camera gltf:1" "--scene .corpus-f/amd/gas_station/GasStation.gltf --camera gltf:0" "--scene atrium"; do
    for m in visibility deferred; do
      extra=""; [ $m = deferred ] && extra="--resolve compute"
      a=$(frame old OLD 8 $scene --method $m $extra --lights 1048576 --light-radius overlap:32 --size 2560x1440)
      for t in 8 16 24; do
        b=$(frame new NEW $t $scene --method $m $extra --lights 1048576 --light-radius overlap:32 --size 2560x1440)
        [ "$a" = "$b" ] && r=identical || r=DIFFERENT
        echo "$scene $m 1048576 lights 2560x1440, block $t: $r ($a $b)"
      done
    done
  done
} > $OUT/frames.txt
for pass in a b; do
  $OLD bench --sweep $D/lighting.sweep.json --backend egl --out $OUT --name old-$pass > $OUT/old-$pass.log 2>&1
  for t in 16 24 8; do
    ML_SCRATCH_LIGHTING_TILE=$t $NEW bench --sweep $D/lighting.sweep.json --backend egl --out $OUT --name new-$t-$pass > $OUT/new-$t-$pass.log 2>&1
  done
done
env LD_LIBRARY_PATH=.devbin/lib .devbin/ml_gpu_tests --gtest_filter='*Deferred*:*Visib*:*Glass*:*Exact*' 2>&1 \
  | grep -v "^\[ RUN\|^\[--" > $OUT/gtest.txt
tar czf $FINAL/lighting.tgz -C /tmp/results lighting
