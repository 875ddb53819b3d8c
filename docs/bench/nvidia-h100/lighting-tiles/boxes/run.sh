#!/usr/bin/env bash
# The lighting pass's workgroup and culling-box sizes (issue 30), one binary whose scratch
# variants are chosen by environment (boxes/scratch.patch), on one machine (nvidia-h100-x1) in one
# command. Carry .devbin.txz, .gl and .corpus-f. Everything lands in $OUT/lighting.tgz.
set -u
D=docs/bench/nvidia-h100/lighting-tiles
FINAL=$OUT
OUT=/tmp/results/lighting
mkdir -p $OUT
[ -d .devbin ] || tar xJf .devbin.txz
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
M="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
# Variants: tile (workgroup side) / box (culling box side) / zero (staging and culling only).
run() {  # name tile box zero
  env ML_SCRATCH_LIGHTING_TILE=$2 ML_SCRATCH_LIGHTING_BOX=$3 ML_SCRATCH_SHADE_ZERO=$4 \
    $M bench --sweep $D/lighting.sweep.json --backend egl --out $OUT --name $1 > $OUT/$1.log 2>&1
}
# Frames first: every variant must give the baseline's frame bit for bit.
for v in "8 8" "16 8" "16 16" "8 4" "16 4"; do
  set -- $v
  env ML_SCRATCH_LIGHTING_TILE=$1 ML_SCRATCH_LIGHTING_BOX=$2 $M render --scene .corpus-f/amd/sponza/Sponza.gltf --camera gltf:1 \
    --method visibility --lights 1048576 --light-radius overlap:32 --size 2560x1440 --backend egl --out-float /tmp/f-$1-$2.pfm --out /tmp/f-$1-$2.png > /dev/null 2>&1
  echo "tile $1 box $2: $(md5sum < /tmp/f-$1-$2.pfm | cut -c1-32)"
done > $OUT/frames.txt
run base-a 8 8 0
run q16-8-a 16 8 0
run t16-a 16 16 0
run c8-4-a 8 4 0
run q16-4-a 16 4 0
run zero8-a 8 8 1
run zero16-8-a 16 8 1
run base-b 8 8 0
run q16-8-b 16 8 0
tar czf $FINAL/lighting.tgz -C /tmp/results lighting
