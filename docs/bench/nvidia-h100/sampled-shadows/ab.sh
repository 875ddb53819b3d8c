#!/usr/bin/env bash
# The A/B of 2026-12-07 (binaries .devbin-split, -cut16, -cut32, -deferred-after packed by tools/pack-for-gpu
# from b7a9ab6+d9bd798, 351e339, 351e339 with 32 entries, 8729b5a). One call, most wanted first, results straight into $OUT so a cut-off call still returns them:
# where the sampled rays are traced (split, cut16, cut32) round a; deferred without (the split
# binary: b7a9ab6's deferred) and with its depth pre-pass; the sampled record (run.sh's sweep)
# with the faster of cut16 and split; round b of the trace A/B. Libraries from .devbin-split/lib.
set -u
D=docs/bench/nvidia-h100/sampled-shadows
R=$OUT/ab
mkdir -p $R
export LD_LIBRARY_PATH=$PWD/.devbin-split/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > $R/gpu.txt
stamp() { echo "$1 rc $2 $(date +%T) $(nvidia-smi --query-gpu=clocks.sm --format=csv,noheader)" | tee -a $R/steps.txt; }
trace() {
  for way in split cut16 cut32; do
    timeout 75 .devbin-$way/manylights bench --sweep $D/trace-pass.sweep.json --backend egl --out $R --name $way-$1 > $R/$way-$1.log 2>&1
    stamp $way-$1 $?
  done
}
trace a
for way in split deferred-after; do
  timeout 140 .devbin-$way/manylights bench --sweep .gpushared/deferred.sweep.json --backend egl --out $R --name deferred-$way > $R/deferred-$way.log 2>&1
  stamp deferred-$way $?
done
total() { python3 -c "import csv,sys; print(sum(float(r['frame_ms'] or 1e9) for r in csv.DictReader(open(sys.argv[1]))))" $1 2>/dev/null || echo 1e12; }
t16=$(total $R/cut16-a.csv); tsplit=$(total $R/split-a.csv)
win=$(python3 -c "print('cut16' if $t16 <= $tsplit else 'split')"); echo "record with $win ($t16 vs $tsplit)" | tee -a $R/steps.txt
timeout 170 .devbin-$win/manylights bench --sweep $D/sampled.sweep.json --backend egl --out $R --name sampled-$win-a > $R/sampled-a.log 2>&1
stamp sampled-$win-a $?
trace b
