#!/usr/bin/env bash
# Issue 14's GPU before/after: the scale preset's deferred and visibility points on four atrium
# cameras and on the boxes scene, for the binary before the real-assets work and after it.
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,clocks.mem --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
CAMS='default;-15,1.7,-6.3,15,1.7,-6.3,60;0,28,0.5,0,0,0,60;-16,3,-4.5,16,1.5,4.5,60'
for b in before after; do
  run() { LD_LIBRARY_PATH=.devbin/$b/lib .devbin/$b/manylights "$@"; }
  run bench --preset scale --method deferred,visibility --lights 1024,16384,65536,1048576 --camera "$CAMS" \
      --warmup 5 --timed-frames 30 --out $OUT --name $b-atrium > $OUT/$b-atrium.log 2>&1
  run bench --preset scale --method deferred,visibility --scene boxes --lights 65536,1048576 \
      --warmup 5 --timed-frames 30 --out $OUT --name $b-boxes > $OUT/$b-boxes.log 2>&1
  tail -n 2 $OUT/$b-atrium.log $OUT/$b-boxes.log
done
kill %1
cd $OUT && tar cf results.tar ./*.csv ./*.json ./*.log ./gpu.txt && rm -f ./*.json ./*.log
