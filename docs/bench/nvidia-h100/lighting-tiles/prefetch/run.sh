#!/usr/bin/env bash
# The light lists' next batch read ahead while the points shade the current one (issue 30),
# before and after on one machine (nvidia-h100-x1) in one command. Before: main at adf15ae
# (.devbin-old); after: the read-ahead (.devbin, prefetch.patch). Carry .devbin.txz, .devbin-old.txz, .gl and
# .corpus-f. Everything lands in $OUT/prefetch.tgz.
set -u
L=docs/bench/nvidia-h100/lighting-tiles
O=docs/bench/nvidia-h100/light-order
FINAL=$OUT
OUT=/tmp/results/prefetch
mkdir -p $OUT
for b in .devbin .devbin-old; do [ -d $b ] || tar xJf $b.txz; done
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
OLD="env LD_LIBRARY_PATH=.devbin-old/lib .devbin-old/manylights"
NEW="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
# Frames: the same lights in the same order, so every frame must be the old binary's bit for bit.
for s in "--scene .corpus-f/amd/gas_station/GasStation.gltf --camera gltf:0" "--scene atrium"; do
  for b in OLD NEW; do
    ${!b} render $s --method visibility --lights 1048576 --light-radius overlap:32 --size 2560x1440 --backend egl --out-float /tmp/$b.pfm --out /tmp/$b.png > /dev/null 2>&1
  done
  cmp -s /tmp/OLD.pfm /tmp/NEW.pfm && echo "$s visibility 1048576 lights: identical" || echo "$s visibility 1048576 lights: DIFFERENT"
done > $OUT/frames.txt
for pass in a b; do
  $OLD bench --sweep $L/lighting.sweep.json --backend egl --out $OUT --name old-$pass > $OUT/old-$pass.log 2>&1
  $NEW bench --sweep $L/lighting.sweep.json --backend egl --out $OUT --name new-$pass > $OUT/new-$pass.log 2>&1
done
tar czf $FINAL/prefetch.tgz -C /tmp/results prefetch  # should the 4M runs run out of time
$OLD bench --sweep $O/4m.sweep.json --backend egl --out $OUT --name old-4m > $OUT/old-4m.log 2>&1
$NEW bench --sweep $O/4m.sweep.json --backend egl --out $OUT --name new-4m > $OUT/new-4m.log 2>&1
tar czf $FINAL/prefetch.tgz -C /tmp/results prefetch
