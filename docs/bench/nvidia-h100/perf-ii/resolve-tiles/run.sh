#!/usr/bin/env bash
# Issue 17, run 5: the resolve over per-texture-set tile lists (perf-e) against the run-4 binary
# it follows (perf-d's numbers are in perf-ii/after*.csv); visibility only, cameras preset and 4M.
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,clocks.mem --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
run() { b=$1; shift; LD_LIBRARY_PATH=.devbin/$b/lib .devbin/$b/manylights "$@"; }
mkdir -p $OUT/r
S='--preset scale --warmup 5 --timed-frames 30'
run perf-e bench --preset cameras --method visibility --out $OUT/r --name resolve-tiles > $OUT/r/a.log 2>&1
run perf-e bench --preset cameras --method visibility --active-only on --out $OUT/r --name resolve-tiles-active-only > $OUT/r/b.log 2>&1
run perf-e bench $S --method visibility --lights 4194304 --size 3840x2160 --camera atrium-set --out $OUT/r --name resolve-tiles-4m > $OUT/r/c.log 2>&1
run perf-e bench $S --method visibility --lights 4194304 --size 3840x2160 --camera atrium-set --active-only on --out $OUT/r --name resolve-tiles-4m-active-only > $OUT/r/d.log 2>&1
kill %1
cp $OUT/gpu.txt $OUT/smclock.csv $OUT/r/
tail -qn 1 $OUT/r/*.log
cd $OUT/r && python3 - <<'PY'
import csv, glob
for f in sorted(glob.glob('resolve*.csv')):
    for r in csv.DictReader(open(f)):
        print(f[:-4], r['lights'], r['camera'][:6], r['frame_ms'][:5], 'raster', r['pass_visibility_raster_ms'][:5], 'resolve', r['pass_visibility_resolve_ms'][:5], r['sm_clock_mhz'], r['note'][:50] if 'error' in r['note'] else '')
PY
cd $OUT && tar cf results.tar r && rm -rf r
