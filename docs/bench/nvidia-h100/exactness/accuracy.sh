#!/usr/bin/env bash
# Issue 29: the GPU accuracy routine under GGX (the default) on the whole corpus (the AMD scenes
# included) and the built-in scenes at their camera sets, 2560x1440, 4,096 lights plus a file's
# own, every method and G-buffer layout; then the layouts' time against error on real content.
set -u
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
M=.devbin/manylights
export LD_LIBRARY_PATH=.devbin/lib
# The corpus in two halves (the GPU machine's carry holds one at a time): CORPUS, and ONLY to keep
# some scenes (the built-in ones come with the first half).
python3 tools/gpu-accuracy --manylights $M --brdf ggx --corpus "${CORPUS:-../shared/corpus}" ${ONLY:+--only $ONLY} \
  --out $OUT/accuracy > $OUT/accuracy.log 2>&1
echo "gpu-accuracy exit $?" >> $OUT/accuracy.log
if [ -n "${LAYOUTS:-}" ]; then
  sed "s#../shared/corpus#${CORPUS:-../shared/corpus}#g" docs/bench/nvidia-h100/layouts/layouts.json > /tmp/layouts.json
  $M bench --sweep /tmp/layouts.json --backend egl --out $OUT --name layouts-h100 > $OUT/layouts.log 2>&1
fi
kill %1
