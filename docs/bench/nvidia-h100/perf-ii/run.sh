#!/usr/bin/env bash
# Issue 17, run 4: the final binary (perf-d: ids by image atomics, no G-buffer clear, overdraw triangle order) against the base 3ea0886.
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,clocks.mem --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
CAMS='default;-15,1.7,-6.3,15,1.7,-6.3,60;0,28,0.5,0,0,0,60;-16,3,-4.5,16,1.5,4.5,60'
run() { b=$1; shift; LD_LIBRARY_PATH=.devbin/$b/lib .devbin/$b/manylights "$@"; }
mkdir -p $OUT/r
run perf-d raster-floors --camera atrium-set --csv $OUT/r/floors.csv 2> $OUT/r/floors.log
S='--preset scale --warmup 5 --timed-frames 30'
run base bench $S --method deferred,visibility --lights 65536,1048576 --camera "$CAMS" --out $OUT/r --name before > $OUT/r/before.log 2>&1
run perf-d bench --preset cameras --out $OUT/r --name after > $OUT/r/after.log 2>&1
run perf-d bench --preset cameras --active-only on --out $OUT/r --name after-active-only > $OUT/r/after-active.log 2>&1
run base bench $S --method visibility --lights 4194304 --size 3840x2160 --camera "$CAMS" --out $OUT/r --name before-4m > $OUT/r/before-4m.log 2>&1
run perf-d bench $S --method visibility --lights 4194304 --size 3840x2160 --camera atrium-set --out $OUT/r --name after-4m > $OUT/r/after-4m.log 2>&1
run perf-d bench $S --method visibility --lights 4194304 --size 3840x2160 --camera atrium-set --active-only on --out $OUT/r --name after-4m-active-only > $OUT/r/after-4m-active.log 2>&1
kill %1
cp $OUT/gpu.txt $OUT/smclock.csv $OUT/r/
tail -qn 1 $OUT/r/*.log
cd $OUT/r && python3 - <<'PY'
import csv, glob
rows = list(csv.DictReader(open('floors.csv')))
print(' '.join('%s/%s=%.3f' % (r['camera'][:4], r['probe'], float(r['ms'])) for r in rows))
for f in sorted(glob.glob('*.csv')):
    if f.startswith(('floors', 'smclock')): continue
    for r in csv.DictReader(open(f)):
        print(f[:-4], r['method'][:3], r['lights'], r['camera'][:6], r['frame_ms'][:5], r.get('pass_visibility_raster_ms','')[:5] or r.get('pass_deferred_gbuffer_ms','')[:5], r.get('sm_clock_mhz',''), r['note'][:40] if 'error' in r['note'] else '')
PY
cd $OUT && tar cf results.tar r && rm -rf r
