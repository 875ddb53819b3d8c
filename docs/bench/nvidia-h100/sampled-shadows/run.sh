#!/usr/bin/env bash
# Issue 63's sampled shadows on the H100 (nvidia-h100-x1), one command: tools/pack-for-gpu's
# .devbin/ (BUILD_DIR=build-test), .gl/ (Debian's GL dispatch, Embree and TBB packages) and
# .gpushared/ (../shared's corpus/amd/ copied in) carried. sampled.sweep.json twice (a, b: the SM
# clock dips on a call's first points), then the atrium at its default camera with the lights
# still, sampled (frame 31 of a sequence from 0) and exact, as PNGs. Every file lands in $OUT/sampled.tgz.
set -u
D=docs/bench/nvidia-h100/sampled-shadows
R=/tmp/results/sampled
mkdir -p $R
export LD_LIBRARY_PATH=$PWD/.devbin/lib
M=.devbin/manylights
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $R/gpu.txt
for run in a b; do
  timeout 170 $M bench --sweep $D/sampled.sweep.json --backend egl --out $R --name sampled-$run > $R/sampled-$run.log 2>&1
done
common="--scene atrium --method visibility --size 1280x720 --lights 65536 --light-radius overlap:32 --drift-speed 0 --backend egl"
timeout 60 $M render $common --shadows sampled --frames 0..31 --out $R/atrium-sampled-%02d.png > $R/atrium-sampled.log 2>&1
for i in $(seq -w 0 30); do rm -f $R/atrium-sampled-$i.png; done
timeout 60 $M render $common --shadows rays --frames 31 --out $R/atrium-rays.png > $R/atrium-rays.log 2>&1
timeout 60 $M render $common --shadows off --frames 31 --out $R/atrium-off.png > $R/atrium-off.log 2>&1
(cd /tmp/results && tar czf $OUT/sampled.tgz sampled)
