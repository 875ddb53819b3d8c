#!/usr/bin/env bash
# Issue 16's GPU measurements (device kind nvidia-h100-x1), 2560x1440, atrium with its glass,
# 65,536 lights of radius overlap:32, exact lists:
#   transparency.csv  the transparent pass per method, glass on and off, on the four committed
#                     cameras (default, gallery, roof, corner); 5 warm-up + 30 timed frames
#   msaa.csv          Forward+ at MSAA 1/2/4/8, deferred and visibility at 1, glass on, default
#                     and corner cameras
#   aa.csv            every method and MSAA level at 1,024 lights, glass on and off, default
#                     camera, each against naive at its sample count and naive supersampled 4 x 4:
#                     the time_vs_aliasing chart
# Run from the repository root with the packed binary in .devbin/i16 and Debian's GL dispatch
# libraries in .gl (docs/bench/README.md, "GPU runs").
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,clocks.mem --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
CAMS='default;-15,1.7,-6.3,15,1.7,-6.3,60;0,28,0.5,0,0,0,60;-16,3,-4.5,16,1.5,4.5,60'
BIN=${BIN:-.devbin/i16}
run() { LD_LIBRARY_PATH=$BIN/lib $BIN/manylights "$@"; }
common=(--lights 65536 --light-radius overlap:32 --size 2560x1440)
if [ "${SKIP_TRANSPARENCY:-0}" != 1 ]; then
  run bench --method forward-plus,deferred,visibility --transparency on,off --camera "$CAMS" "${common[@]}" \
      --warmup 5 --timed-frames 30 --out $OUT --name transparency > $OUT/transparency.log 2>&1
fi
if [ "${SKIP_MSAA:-0}" != 1 ]; then
# The MSAA levels' time at 65,536 lights (the naive budget skips accuracy: one naive frame is 20 s).
run bench --method forward-plus,deferred,visibility --msaa 1,2,4,8 --camera "default;-16,3,-4.5,16,1.5,4.5,60" "${common[@]}" \
    --warmup 5 --timed-frames 30 --out $OUT --name msaa > $OUT/msaa.log 2>&1
fi
# Time against aliasing error: naive supersampled 4 x 4 is one draw of 10240x5760 pixels, and on
# this GPU a naive draw past about 1e11 pixel-lights comes back wrong (a 16,384-light reference at
# 5120x2880, 2.4e11, was 3 dB from every method; one of 1,024 lights at 10240x5760, 6e10, agrees
# to 52 dB), so the chart's points have 1,024 lights, glass on and off, naive included.
run bench --method naive,forward-plus,deferred,visibility --msaa 1,2,4,8 --transparency on,off --lights 1024 \
    --light-radius overlap:32 --size 2560x1440 --reference supersampled:4 --warmup 5 --timed-frames 30 \
    --out $OUT --name aa > $OUT/aa.log 2>&1
tail -n 3 $OUT/*.log
kill %1
cd $OUT && tar cf results.tar ./*.csv ./*.json ./*.log ./gpu.txt && rm -f ./*.json ./*.log
