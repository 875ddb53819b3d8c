#!/usr/bin/env bash
# Issue 24, run 4: the counts cleared by compute.
set -u
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm,clocks.mem --format=csv > $OUT/gpu.txt
(while true; do nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,power.draw --format=csv,noheader >> $OUT/smclock.csv; sleep 1; done) &
run() { b=$1; shift; LD_LIBRARY_PATH=.dev-24/$b/lib .dev-24/$b/manylights "$@" --backend egl; }
mkdir -p $OUT/r
S='--preset scale --warmup 5 --timed-frames 30 --method visibility --camera atrium-set'
run . bench $S --lights 65536,1048576 --out $OUT/r --name after4 > $OUT/r/after4.log 2>&1
run . bench $S --lights 4194304 --size 3840x2160 --out $OUT/r --name after4-4m > $OUT/r/after4-4m.log 2>&1
kill %1
cp $OUT/gpu.txt $OUT/smclock.csv $OUT/r/
tail -qn 1 $OUT/r/*.log
cd $OUT/r && python3 - <<'PY'
import csv, glob
def g(r,k):
    v=r.get(k,'');return float(v) if v else 0.0
for f in sorted(glob.glob('*.csv')):
    if f.startswith('smclock'): continue
    for r in csv.DictReader(open(f)):
        print(f[:-4], r['method'][:4], r['lights'], r['camera'][:8], 'frame %.3f' % g(r,'frame_ms'), ' '.join('%s=%.3f' % (k[5:-3].replace('visibility_','v.'), g(r,k)) for k in r if k.startswith('pass_') and k.endswith('_ms') and 'transparent' in k), r.get('sm_clock_mhz',''), 'ldrmax', r.get('ldr_max_abs_err','')[:8])
PY
cd $OUT && tar cf results4.tar r && rm -rf r
