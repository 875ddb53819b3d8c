#!/usr/bin/env python3
"""A before/after table from two runs of a sweep, each done twice (NAME-a.csv, NAME-b.csv, in
the current folder): per point (experiment, camera, raster), of the two passes that ran at the
full 1980 MHz, the one with the lower frame time; a point with no full-clock pass on a side is
left out of that side's range and counted. One pass's column (default: count + fill).
  summarize.py OLD NEW [COLUMN]   e.g. targets-old targets-new-run-8 (assign-runs/),
                                  targets-old targets-new pass_assign_sort_ms (sort-chunks/)"""
import csv, sys
from collections import defaultdict

def load(name):
    rows = defaultdict(list)
    for p in 'ab':
        for r in csv.DictReader(open(f'{name}-{p}.csv')):
            rows[(r['experiment'], r['camera'], r['vis_raster'] if r['method'] == 'visibility' else '-')].append(r)
    best = {}
    for k, rs in rows.items():
        full = [r for r in rs if r['sm_clock_mhz'] == '1980']
        if full: best[k] = min(full, key=lambda r: float(r['frame_ms']))
    return best, len(rows)

column = sys.argv[3] if len(sys.argv) > 3 else None
label = column[5:-3].replace('_', ' ') if column else 'count + fill'
def cf(r): return float(r[column]) if column else float(r['pass_assign_count_ms']) + float(r['pass_assign_fill_ms'])
old, n = load(sys.argv[1])
new, _ = load(sys.argv[2])
groups = defaultdict(lambda: defaultdict(list))
for k in set(old) | set(new):
    g = (k[0], k[2])
    for side, d in (('old', old), ('new', new)):
        if k in d: groups[g][side].append(d[k])
rng = lambda xs: f'{min(xs):.2f}–{max(xs):.2f}' if xs else 'n/a'
print(f'| experiment | raster | {label} before | after | frame before | after | points at 1980 MHz (before/after) |')
print('|---|---|---|---|---|---|---|')
for g in sorted(groups):
    o, w = groups[g]['old'], groups[g]['new']
    print(f"| {g[0]} | {g[1]} | {rng([cf(r) for r in o])} | {rng([cf(r) for r in w])} | {rng([float(r['frame_ms']) for r in o])} | {rng([float(r['frame_ms']) for r in w])} | {len(o)}/{len(w)} |")
