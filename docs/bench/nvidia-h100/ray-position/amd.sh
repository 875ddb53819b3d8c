#!/usr/bin/env bash
# tools/gpu-accuracy after the ray-position change on the AMD files (Sponza's four cameras and its
# alpha-tested foliage, the gas station's two and its glass) and the built-in scenes, on the H100
# (nvidia-h100-x1). Carry .devbin.txz, .gl and .corpus-amd. Lands in $OUT/amd.tgz.
set -u
FINAL=$OUT
OUT=/tmp/results/amd
mkdir -p $OUT
[ -d .devbin ] || tar xJf .devbin.txz
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
export LD_LIBRARY_PATH=$PWD/.devbin/lib
timeout 300 python3 tools/gpu-accuracy --manylights .devbin/manylights --corpus $PWD/.corpus-amd/corpus \
  --only Sponza,GasStation,plane --out $OUT/accuracy > $OUT/accuracy.log 2>&1
echo "gpu-accuracy exit $?" >> $OUT/exits.txt
tar czf $FINAL/amd.tgz -C /tmp/results amd
