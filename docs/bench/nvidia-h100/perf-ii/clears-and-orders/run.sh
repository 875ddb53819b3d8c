#!/usr/bin/env bash
# Issue 17, run 2: floors per triangle order; the cameras sweep before (base 3ea0886) and after
# (perf-b: no id/G-buffer clears), triangle orders, --active-only at 1M, 4M lights at 3840x2160.
set -u
for f in .gl/*.deb; do dpkg -x $f /; done; ldconfig
export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,clocks.mem --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
CAMS='default;-15,1.7,-6.3,15,1.7,-6.3,60;0,28,0.5,0,0,0,60;-16,3,-4.5,16,1.5,4.5,60'
run() { b=$1; shift; LD_LIBRARY_PATH=.devbin/$b/lib .devbin/$b/manylights "$@"; }
mkdir -p $OUT/r
for o in as-loaded vertex-cache overdraw; do
  run perf-b raster-floors --camera atrium-set --triangle-order $o --csv $OUT/r/floors-$o.csv 2>> $OUT/r/floors.log
done
run perf-b raster-floors --camera atrium-set --detail 0.5 --csv $OUT/r/floors-detail-0.5.csv 2>> $OUT/r/floors.log
B='--scene atrium --size 2560x1440 --radius overlap:32 --assign exact --warmup 5 --timed-frames 30'
run base bench $B --method deferred,visibility --lights 65536,1048576 --camera "$CAMS" --out $OUT/r --name before > $OUT/r/before.log 2>&1
run perf-b bench --preset cameras --out $OUT/r --name after > $OUT/r/after.log 2>&1
run perf-b bench --preset cameras --lights 65536 --triangle-order vertex-cache,overdraw --out $OUT/r --name orders > $OUT/r/orders.log 2>&1
run perf-b bench --preset cameras --lights 1048576 --method visibility --active-only on --out $OUT/r --name active-only > $OUT/r/active.log 2>&1
run base bench $B --method visibility --lights 4194304 --size 3840x2160 --camera "$CAMS" --out $OUT/r --name before-4m > $OUT/r/before-4m.log 2>&1
run perf-b bench $B --method visibility --lights 4194304 --size 3840x2160 --camera atrium-set --out $OUT/r --name after-4m > $OUT/r/after-4m.log 2>&1
kill %1
cp $OUT/gpu.txt $OUT/smclock.csv $OUT/r/
tail -n 2 $OUT/r/*.log
cd $OUT/r && python3 - <<'PY'
import csv, glob
for f in sorted(glob.glob('*.csv')):
    if f.startswith('floors'):
        rows = list(csv.DictReader(open(f)))
        print(f, ' '.join('%s/%s=%.3f' % (r['camera'][:6], r['probe'], float(r['ms'])) for r in rows if r['probe'] in ('scene','clear-depth','clear-ids','fullscreen','scene-depth-only','scene-no-raster') and r['camera'] in ('default','0,28,0.5,0,0,0,60')))
    elif f != 'smclock.csv':
        for r in csv.DictReader(open(f)):
            print(f, r['method'], r['lights'], r['camera'][:8], r.get('triangle_order',''), r.get('active_only',''), r['frame_ms'][:5], r.get('pass_visibility_raster_ms','')[:5], r.get('pass_deferred_gbuffer_ms','')[:5], r.get('sm_clock_mhz',''), r['note'][:60])
PY
cd $OUT && tar cf results.tar r && rm -rf r
