#!/usr/bin/env bash
# exploring call 3: the tile pass's rows per invocation in 16x16 tiles, with 8x8 tiles for small bounds
set -u
REAL=$OUT; OUT=/root/res-rows; rm -rf $OUT; mkdir -p $OUT
[ -d .devbin-lib ] || tar xJf .devbin-rw.txz
if [ ! -d .corpus-sponza ]; then mkdir -p .corpus-sponza && cat .sponza-part0 .sponza-part1 .sponza-part2 .sponza-part3 | tar x -C .corpus-sponza; fi
export LD_LIBRARY_PATH=$PWD/.devbin-lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
for b in fin2 r8; do .devbin-$b/manylights render --backend egl --method visibility --vis-raster compute --size 320x180 --lights 64 --out /tmp/q-$b.png > $OUT/quick-$b.log 2>&1 || { echo "quick $b failed"; cat $OUT/quick-$b.log; exit 1; }; done
echo quick ok
timeout 60 .devbin-r8/manylights bench --scene atrium --lights 1048576 --size 2560x1440 --warmup 5 --timed-frames 600 --backend egl --out /tmp/warm --name warm > /dev/null 2>&1
echo warmed $(date +%T)
for r in 1 2 3; do
  for b in fin2 r4 r8 r2; do
    timeout 200 .devbin-$b/manylights bench --sweep .exp/explore.sweep.json --backend egl --out $OUT --name t-$b-$r > $OUT/t-$b-$r.log 2>&1
  done
  echo "round $r $(date +%T)"
  tar czf $REAL/res.tgz -C $OUT .
done
