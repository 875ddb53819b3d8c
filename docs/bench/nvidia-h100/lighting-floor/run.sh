#!/usr/bin/env bash
# Issue 30: what the shading of the lights that add light costs in the lighting pass, on the
# H100 (nvidia-h100-x1). Carry .gl, .devbin.txz (main: manylights and its libraries),
# .devbin-twice.txz (main with twice.patch: its manylights alone) and .corpus-sponza
# (corpus/amd/sponza) or .corpus-gas (corpus/amd/gas_station): the sweep skips the file it lacks.
#   run.sh <n>   floor.sweep.json with main, then the patched build, named -<n>; and both builds'
#                float frames at the atrium's default camera, 65,536 lights (frames.txt: whether
#                they are identical, as the patch adds zeros)
set -u
D=docs/bench/nvidia-h100/lighting-floor
for b in .devbin*.txz; do [ -d ${b%.txz} ] || tar xJf $b; done
export LD_LIBRARY_PATH=$PWD/.devbin/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
sweep=$OUT/floor.sweep.json
python3 - $D/floor.sweep.json $sweep <<'PY'
import json, os, sys
d = json.load(open(sys.argv[1]))
d["experiments"] = [e for e in d["experiments"] if e["scene"] == "atrium" or os.path.exists(e["scene"])]
json.dump(d, open(sys.argv[2], "w"), indent=1)
PY
for build in "" -twice; do
  label=${build:--main}
  .devbin$build/manylights bench --sweep $sweep --backend egl --out $OUT --name floor$label-$1 > $OUT/floor$label-$1.log 2>&1
  .devbin$build/manylights render --scene atrium --method visibility --lights 65536 --light-radius overlap:32 --size 2560x1440 \
    --backend egl --out-float /tmp/frame$label.pfm --out /tmp/frame$label.png > /dev/null 2>&1
done
cmp -s /tmp/frame-main.pfm /tmp/frame-twice.pfm && echo "atrium default visibility 65536 lights: identical" > $OUT/frames.txt \
  || echo "atrium default visibility 65536 lights: DIFFERENT" > $OUT/frames.txt
