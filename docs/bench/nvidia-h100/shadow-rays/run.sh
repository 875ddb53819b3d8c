#!/usr/bin/env bash
# Issue 62's shadow rays on the H100 (nvidia-h100-x1), one command: tools/pack-for-gpu's .devbin/
# (BUILD_DIR=build-test), .gl/ (Debian's GL dispatch, Embree and TBB packages) and .gpushared/
# (../shared's repro/ and corpus/amd/ copied in) carried.
#   run.sh repro     issue 61's repro files in every method (PNG each, and the max over the quad)
#   run.sh bench     half a minute of frames to raise the SM clock, then shadows.sweep.json twice (a, b)
#   run.sh accuracy  accuracy.sweep.json: every method against naive with the same rays
#   run.sh bounds    half a minute of frames, then bounds.sweep.json: the rate against the lights' reach
#   run.sh layout    half a minute of frames, then layout.sweep.json: the node layout (2, 4, 8 children)
#   run.sh animated  animated.sweep.json (the refit's cost) and --stats of each animated file (Embree's build)
# Every file lands in $OUT/STEP.tgz.
set -u
D=docs/bench/nvidia-h100/shadow-rays
STEP=$1
FINAL=$OUT
OUT=/tmp/results/$STEP
mkdir -p $OUT
export LD_LIBRARY_PATH=$PWD/.devbin/lib
M=.devbin/manylights
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
pack() { tar czf $FINAL/$STEP.tgz -C /tmp/results $STEP; }
case "$STEP" in
repro)
  for file in quad quad_after_unused_vertices; do
    for method in naive forward-plus deferred visibility; do
      timeout 60 $M render --scene .gpushared/repro/$file.gltf --method $method --exposure 0 --backend egl \
        --out $OUT/$file-$method.png > $OUT/$file-$method.log 2>&1
    done
  done ;;
bench)
  timeout 30 $M bench --scene atrium --lights 65536 --size 2560x1440 --light-radius overlap:32 --method visibility \
    --warmup 5 --timed-frames 600 --backend egl --out /tmp/warm --name warm > $OUT/warm.log 2>&1
  for run in a b; do
    timeout 250 $M bench --sweep $D/shadows.sweep.json --backend egl --out $OUT --name shadows-$run > $OUT/shadows-$run.log 2>&1
    pack
  done ;;
bounds)
  timeout 30 $M bench --scene atrium --lights 65536 --size 2560x1440 --light-radius overlap:32 --method visibility \
    --warmup 5 --timed-frames 600 --backend egl --out /tmp/warm --name warm > $OUT/warm.log 2>&1
  timeout 400 $M bench --sweep $D/bounds.sweep.json --backend egl --out $OUT --name bounds > $OUT/bounds.log 2>&1 ;;
layout)
  timeout 30 $M bench --scene atrium --lights 65536 --size 2560x1440 --light-radius overlap:32 --method visibility \
    --warmup 5 --timed-frames 600 --backend egl --out /tmp/warm --name warm > $OUT/warm.log 2>&1
  timeout 500 $M bench --sweep $D/layout.sweep.json --backend egl --out $OUT --name layout > $OUT/layout.log 2>&1 ;;
animated)
  timeout 200 $M bench --sweep $D/animated.sweep.json --backend egl --out $OUT --name animated > $OUT/animated.log 2>&1
  for file in .gpushared/corpus/khronos/CesiumMan/glTF/CesiumMan.gltf .gpushared/corpus/amd/gas_station/GasStation.gltf; do
    timeout 60 $M render --scene $file --shadows rays --size 2560x1440 --lights 65536 --light-radius overlap:32 --method visibility \
      --backend egl --stats --time --out $OUT/$(basename $file .gltf).png > $OUT/$(basename $file .gltf).log 2>&1
  done ;;
accuracy)
  timeout 300 $M bench --sweep $D/accuracy.sweep.json --backend egl --out $OUT --name accuracy > $OUT/accuracy.log 2>&1 ;;
*)
  echo "run.sh: unknown step '$STEP' (repro, bench, accuracy, bounds, layout, animated)" >&2
  exit 2 ;;
esac
pack
