#!/usr/bin/env bash
# Issue 30's glass lever on the H100 (nvidia-h100-x1), before and after in one command: .devbin-old
# (main at 5b1113b: each glass fragment walks its cluster's list from global memory) and .devbin
# (the tile's fragments served their lists from shared memory, include/list_rounds.glsl), the
# same sweep (timing.sweep.json), then both binaries' frames compared byte for byte. Carry .devbin,
# .devbin-old, .gl and .corpus-e (the gas station).
set -u
D=docs/bench/nvidia-h100/glass-rounds
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
for build in old new; do
  if [ $build = old ]; then B=.devbin-old; else B=.devbin; fi
  env LD_LIBRARY_PATH=$B/lib $B/manylights bench --sweep $D/timing.sweep.json --backend egl --out $OUT --name $build > /tmp/$build.log 2>&1
  mkdir -p /tmp/frames/$build
  for scene in atrium .corpus-e/amd/gas_station/GasStation.gltf; do
    for m in visibility deferred; do
      env LD_LIBRARY_PATH=$B/lib $B/manylights render --scene $scene --method $m --lights 65536 --size 2560x1440 --backend egl \
        --out /tmp/frames/$build/$(basename $scene .gltf)-$m.png > /dev/null 2>&1
    done
  done
done
for f in /tmp/frames/old/*.png; do
  if cmp -s "$f" "/tmp/frames/new/$(basename "$f")"; then echo "identical $(basename "$f")"; else echo "DIFFERENT $(basename "$f")"; fi
done > $OUT/frames.txt
tar czf $OUT/logs.tgz -C /tmp old.log new.log
