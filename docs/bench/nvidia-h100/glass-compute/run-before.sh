#!/usr/bin/env bash
# Issue 24: glass captured and shaded in compute (.dev-24) against the base 161fbb5 (.dev-24/before).
set -u
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,clocks.mem --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
run() { b=$1; shift; LD_LIBRARY_PATH=.dev-24/$b/lib .dev-24/$b/manylights "$@" --backend egl; }
mkdir -p $OUT/r
S='--preset scale --warmup 5 --timed-frames 30 --method visibility --camera atrium-set'
run . bench $S --lights 65536,1048576 --out $OUT/r --name after > $OUT/r/after.log 2>&1
run before bench $S --lights 65536,1048576 --out $OUT/r --name before > $OUT/r/before.log 2>&1
run . bench $S --lights 4194304 --size 3840x2160 --out $OUT/r --name after-4m > $OUT/r/after-4m.log 2>&1
run before bench $S --lights 4194304 --size 3840x2160 --out $OUT/r --name before-4m > $OUT/r/before-4m.log 2>&1
# Exactness against naive with the glass, every method, the four cameras (naive affordable at 1,024 lights).
run . bench --preset scale --warmup 1 --timed-frames 3 --method naive,forward-plus,deferred,visibility --lights 1024 --camera atrium-set --out $OUT/r --name exact-after > $OUT/r/exact.log 2>&1
# The capture's memory per camera at 2560x1440 and 3840x2160, and pictures to look at.
for cam in default -15,1.7,-6.3,15,1.7,-6.3,60 0,28,0.5,0,0,0,60 -16,3,-4.5,16,1.5,4.5,60; do
  for size in 2560x1440 3840x2160; do
    echo "camera $cam $size" >> $OUT/r/stats.txt
    run . render --scene atrium --method visibility --lights 1024 --size $size --camera=$cam --stats --out /tmp/x.png 2>&1 | grep -i "transparency:\|error" >> $OUT/r/stats.txt
  done
done
run . render --scene atrium --method visibility --lights 1024 --size 1280x720 --camera=-16,3,-4.5,16,1.5,4.5,60 --out $OUT/r/corner-after.png > /dev/null 2>&1
run before render --scene atrium --method visibility --lights 1024 --size 1280x720 --camera=-16,3,-4.5,16,1.5,4.5,60 --out $OUT/r/corner-before.png > /dev/null 2>&1
kill %1
cp $OUT/gpu.txt $OUT/smclock.csv $OUT/r/
tail -qn 1 $OUT/r/*.log
cat $OUT/r/stats.txt
cd $OUT/r && python3 - <<'PY'
import csv, glob
for f in sorted(glob.glob('*.csv')):
    if f.startswith('smclock'): continue
    for r in csv.DictReader(open(f)):
        tr = sum(float(v) for k, v in r.items() if k.startswith('pass_') and 'transparent' in k and v)
        print(f[:-4], r['method'][:4], r['lights'], r['camera'][:8], 'frame', r['frame_ms'][:6], 'transp %.3f' % tr, r.get('sm_clock_mhz',''), 'ldrmax', r.get('ldr_max_abs_err','')[:8], 'psnr', r.get('psnr_db','')[:6], r['note'][:60] if 'error' in r.get('note','') else '')
PY
cd $OUT && tar cf results.tar r && rm -rf r
