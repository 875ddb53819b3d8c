#!/usr/bin/env bash
# Naive's frame on the H100 by build: the README's 1,024-light point (--preset scale, 2560x1440,
# one camera, 5 frames after 3) with each build of BUILDS ('label:folder ...'), stripped
# executables unpacked from the .devbin-*.txz archives carried beside .gl (tools/pack-for-gpu's
# libraries in .devbin-lib/). It found the commit that made naive 3.2 times slower (e1f6e41, the
# glass's capture window, between ec5eb59 and 2d1a529) and measured the mend (c9faddc).
set -u
[ -d .devbin-lib ] || for a in .devbin-*.txz; do tar xJf $a; done
export LD_LIBRARY_PATH=$PWD/.devbin-lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $OUT/gpu.txt
for build in $BUILDS; do
  timeout 120 ${build#*:}/manylights bench --preset scale --warmup 3 --timed-frames 5 --camera ${CAMERA:-default} --backend egl \
    --method naive --lights 1024 --out $OUT --name naive-${build%:*} > $OUT/naive-${build%:*}.log 2>&1
done
