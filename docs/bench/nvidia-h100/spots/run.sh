#!/usr/bin/env bash
# Issue 15 on the GPU: half spots against points only (spots preset, four atrium cameras), the
# accuracy of spots against naive at 16,384 lights, and points-only cost against the binary
# before the light model changed (issue 14's).
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
CAMS='default;-15,1.7,-6.3,15,1.7,-6.3,60;0,28,0.5,0,0,0,60;-16,3,-4.5,16,1.5,4.5,60'
run() { b=$1; shift; LD_LIBRARY_PATH=.devbin/$b/lib .devbin/$b/manylights "$@"; }
run lights bench --preset spots --lights 16384,65536,1048576 --camera "$CAMS" --warmup 5 --timed-frames 30 --out $OUT --name spots > $OUT/spots.log 2>&1
for b in after lights; do
  run $b bench --preset scale --method deferred,visibility --lights 65536,1048576 --warmup 5 --timed-frames 30 --out $OUT --name points-$b > $OUT/points-$b.log 2>&1
done
kill %1
tail -n 3 $OUT/*.log
cd $OUT && tar cf results.tar ./*.csv ./*.json ./*.log ./gpu.txt && rm -f ./*.json ./*.log
