#!/usr/bin/env bash
# Issue 30: the exact lists sized by their candidate pairs, read behind a fence, on the H100
# (nvidia-h100-x1). Carry .gl and the builds the case names, each packed as .devbin<suffix>.txz
# (tools/pack-for-gpu; besides .devbin, the manylights binary alone, run with .devbin's libraries):
#   .devbin         the change (the lists sized behind the fence, a glFlush after the fill;
#                   manylights, ml_gpu_tests, ml_corpus_tests)
#   .devbin-old     main before it (71b840b): the lists' total read back between scan and fill
#   .devbin-noflush the change without the glFlush (rounds 1-3)
#   .devbin-split   the change with the glass count and the resolve queued between the count
#                   and the fill (split.patch; rounds 4-6)
# and .corpus-gas (corpus/amd/gas_station) or .corpus-sponza (corpus/amd/sponza).
#   run.sh round <n> <suffix>...  lists.sweep.json with each build in turn ("" is .devbin),
#                                 named lists-<suffix or -fence>-<n>
#   run.sh sponza                 sponza.sweep.json, before and after, twice, interleaved
#   run.sh headline               the README's results table (--preset scale, every method in
#                                 its defaults, atrium-set), and visibility with the compute raster
#   run.sh tests                  every GPU test (gpu-tests.txt)
set -u
D=docs/bench/nvidia-h100/list-sync
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
case "$1" in
round)
  n=$2; shift 2
  for build in "$@"; do
    label=${build:--fence}
    timeout 200 .devbin$build/manylights bench --sweep $D/lists.sweep.json --backend egl --out $OUT --name lists$label-$n \
      > $OUT/lists$label-$n.log 2>&1
  done ;;
sponza)
  n=0
  for build in -old "" -old ""; do
    n=$((n + 1)); label=${build:--fence}
    .devbin$build/manylights bench --sweep $D/sponza.sweep.json --backend egl --out $OUT --name sponza$label-$n \
      > $OUT/sponza$label-$n.log 2>&1
  done ;;
headline)
  S='--preset scale --warmup 5 --timed-frames 30 --camera atrium-set --backend egl'
  M=.devbin/manylights
  $M bench $S --method naive,forward-plus,deferred,visibility --lights 1024 --out $OUT --name headline-1k > $OUT/headline-1k.log 2>&1
  $M bench $S --method forward-plus,deferred,visibility --lights 65536 --out $OUT --name headline-64k > $OUT/headline-64k.log 2>&1
  $M bench $S --method deferred,visibility --lights 1048576 --out $OUT --name headline-1m > $OUT/headline-1m.log 2>&1
  for n in 1024:1k 65536:64k 1048576:1m; do
    $M bench $S --method visibility --vis-raster compute --lights ${n%:*} --out $OUT --name compute-${n#*:} > $OUT/compute-${n#*:}.log 2>&1
  done ;;
tests)
  mkdir -p /work/main/build-test /work/shared
  ln -sf $PWD/.devbin/manylights /work/main/build-test/manylights
  [ -d .corpus-sponza ] && ln -sfn $PWD/.corpus-sponza/corpus /work/shared/corpus
  timeout 400 .devbin/ml_gpu_tests 2>&1 | grep -v "^\[ RUN\|^\[--" > $OUT/gpu-tests.txt ;;
esac
