#!/usr/bin/env bash
# Issue 17's targets measured again on main after issues 16 and 17 merged (device kind
# nvidia-h100-x1): the atrium now has glass, so every point runs with --transparency off (the
# opaque atrium the targets were set for) and on; the camera set atrium-set; deferred and the
# visibility buffer at 65,536 and 1,048,576 lights (2560x1440) and the visibility buffer at
# 4,194,304 (3840x2160), each with and without --active-only. Then frame 60 at 1,024 lights by
# naive, visibility (packed and standard G-buffer) and deferred as PNGs, to find the pixels the
# visibility buffer leaves off naive on this GPU (issue 17, "Accuracy on the GPU").
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,clocks.mem --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
BIN=${BIN:-.devbin/i16}
run() { LD_LIBRARY_PATH=$BIN/lib $BIN/manylights "$@"; }
if [ "${SKIP_BENCH:-0}" != 1 ]; then
run bench --preset cameras --transparency off,on --active-only off,on --out $OUT --name cameras > $OUT/cameras.log 2>&1
run bench --method visibility --lights 4194304 --light-radius overlap:32 --size 3840x2160 --camera atrium-set \
    --transparency off,on --active-only off,on --warmup 5 --timed-frames 30 --out $OUT --name 4m > $OUT/4m.log 2>&1
fi
c=(--lights 1024 --size 2560x1440 --frames 60)
run render --method naive "${c[@]}" --out $OUT/naive.png
run render --method visibility "${c[@]}" --out $OUT/visibility.png
run render --method visibility --gbuffer standard "${c[@]}" --out $OUT/visibility-standard.png
run render --method deferred "${c[@]}" --out $OUT/deferred.png
tail -n 2 $OUT/*.log
kill %1
cd $OUT && tar cf results.tar ./*.csv ./*.json ./*.log ./gpu.txt && rm -f ./*.json ./*.log ./*.csv
