#!/usr/bin/env bash
# The exact count and fill in runs of candidates (issue 30), before and after on one machine
# (nvidia-h100-x1) in one command. Before: main at 5e3d4bc (.devbin-old); after: the runs
# (.devbin; both with ml_gpu_tests). Carry .devbin.txz, .devbin-old.txz, .gl and .corpus-f (Sponza
# and the gas station). The run-length sweep needs a scratch build whose exactProgram passes
# ML_SCRATCH_CANDIDATE_RUN from the environment as ML_CANDIDATE_RUN (one line, not on main);
# on main the length is ML_ASSIGN_CANDIDATE_RUN in glsl/include/bindings.h.
#   run.sh           the sweeps below; everything lands in $OUT/runs.tgz
#   run.sh headline  the README's results table on main (.devbin, the runs at their default of 8,
#                    no scratch line), with 5e3d4bc's deferred and visibility beside it: $OUT/headline.tgz
set -u
D=docs/bench/nvidia-h100/assign-runs
LABEL=runs; [ "${1:-}" = headline ] && LABEL=headline
FINAL=$OUT
OUT=/tmp/results/$LABEL
mkdir -p $OUT
for b in .devbin .devbin-old; do [ -d $b ] || tar xJf $b.txz; done
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
OLD="env LD_LIBRARY_PATH=.devbin-old/lib .devbin-old/manylights"
NEW="env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"
if [ $LABEL = headline ]; then
  S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
  $NEW bench $S --method naive,forward-plus,deferred,visibility --lights 1024 --out $OUT --name new-1k > $OUT/new-1k.log 2>&1
  $NEW bench $S --method forward-plus,deferred,visibility --lights 65536 --out $OUT --name new-64k > $OUT/new-64k.log 2>&1
  $NEW bench $S --method deferred,visibility --lights 1048576 --out $OUT --name new-1m > $OUT/new-1m.log 2>&1
  $OLD bench $S --method deferred,visibility --lights 65536 --out $OUT --name old-64k > $OUT/old-64k.log 2>&1
  $OLD bench $S --method deferred,visibility --lights 1048576 --out $OUT --name old-1m > $OUT/old-1m.log 2>&1
  tar czf $FINAL/$LABEL.tgz -C /tmp/results $LABEL
  exit 0
fi
# Frames: the lists are sorted, so the runs must leave every method's frame byte-identical.
for m in forward-plus deferred visibility; do
  for build in old new; do
    M=OLD; [ $build = new ] && M=NEW
    ${!M} render --scene atrium --method $m --lights 65536 --size 1280x720 --backend egl --out /tmp/$build-$m.png > /dev/null 2>&1
  done
  cmp -s /tmp/old-$m.png /tmp/new-$m.png && echo "$m 65536 lights 1280x720: byte-identical" || echo "$m 65536 lights 1280x720: DIFFERENT"
done > $OUT/frames.txt
# Before and after twice, interleaved, as the H100's clock falls on some points.
for pass in a b; do
  $OLD bench --sweep $D/targets.sweep.json --backend egl --out $OUT --name targets-old-$pass > $OUT/targets-old-$pass.log 2>&1
  for run in 4 8; do
    ML_SCRATCH_CANDIDATE_RUN=$run $NEW bench --sweep $D/targets.sweep.json --backend egl --out $OUT --name targets-new-run-$run-$pass > $OUT/targets-new-run-$run-$pass.log 2>&1
  done
done
for run in 1 2 4 8 16; do
  ML_SCRATCH_CANDIDATE_RUN=$run $NEW bench --sweep $D/runs.sweep.json --backend egl --out $OUT --name run-$run > $OUT/run-$run.log 2>&1
done
T='Grids/LightAssignment.*:GpuTest.ExactLists*:Sort/*'
env LD_LIBRARY_PATH=.devbin/lib .devbin/ml_gpu_tests --gtest_filter="$T" 2>&1 | grep -v "^\[ RUN\|^\[--" > $OUT/gtest.txt
tar czf $FINAL/$LABEL.tgz -C /tmp/results $LABEL
