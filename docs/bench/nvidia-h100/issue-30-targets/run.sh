#!/usr/bin/env bash
# Issue 30 before and after on one machine (nvidia-h100-x1), in two commands. Before: main at
# bbdf756 (.devbin-old), where the issue's figures were taken; after: main (.devbin). Carry
# .devbin.txz, .devbin-old.txz, .gl and .corpus-f (Sponza and the gas station).
#   run.sh headline  the README's results table: --preset scale on atrium-set, every method
#   run.sh targets   the issue's target rows (targets-*.sweep.json) and raster-floors with the compute raster
# Committed: headline/ and targets/ (run a), targets-b/ (the same again, later on one machine).
set -u
D=docs/bench/nvidia-h100/issue-30-targets
# Every file lands in one archive, $OUT/LABEL.tgz (the device tool returns at most 8 files);
# LABEL is the first argument, with the second appended for a repeat (run.sh targets b).
LABEL=$1${2:+-$2}
FINAL=$OUT
OUT=/tmp/results/$LABEL
mkdir -p $OUT
for b in .devbin .devbin-old; do [ -d $b ] || tar xJf $b.txz; done
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
binary() { if [ $1 = old ]; then echo "env LD_LIBRARY_PATH=.devbin-old/lib .devbin-old/manylights"; else echo "env LD_LIBRARY_PATH=.devbin/lib .devbin/manylights"; fi; }
case "$1" in
headline)
  S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
  for build in old new; do
    M=$(binary $build)
    $M bench $S --method naive,forward-plus,deferred,visibility --lights 1024 --out $OUT --name $build-1k > /tmp/$build-1k.log 2>&1
    $M bench $S --method forward-plus,deferred,visibility --lights 65536 --out $OUT --name $build-64k > /tmp/$build-64k.log 2>&1
    $M bench $S --method deferred,visibility --lights 1048576 --out $OUT --name $build-1m > /tmp/$build-1m.log 2>&1
  done
  cp /tmp/old-1k.log /tmp/old-64k.log /tmp/old-1m.log /tmp/new-1k.log /tmp/new-64k.log /tmp/new-1m.log $OUT ;;
targets)
  for build in old new; do
    $(binary $build) bench --sweep $D/targets-$build.sweep.json --backend egl --out $OUT --name targets-$build > /tmp/targets-$build.log 2>&1
  done
  $(binary new) raster-floors --scene atrium --camera atrium-set --size 2560x1440 --backend egl --csv $OUT/raster-floors.csv > /tmp/floors.log 2>&1
  cp /tmp/targets-old.log /tmp/targets-new.log /tmp/floors.log $OUT ;;
esac
tar czf $FINAL/$LABEL.tgz -C /tmp/results $LABEL
