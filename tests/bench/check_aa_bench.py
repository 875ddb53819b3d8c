#!/usr/bin/python3
"""A tiny `manylights bench` with `--reference supersampled:2` over methods x MSAA levels on
llvmpipe, then `tools/plot --only time_vs_aliasing` on its CSV.

Checks that every point has finite aa_rmse and aa_psnr_db, that MSAA 4 comes closer to the
supersampled reference than MSAA 1, that deferred (one sample per pixel) runs beside the MSAA
points without an msaa value, that a sweep of deferred alone with --msaa 4 is refused in one
line, and that the chart is written. Asserts no timing.

    check_aa_bench.py --manylights BIN --plot tools/plot --out DIR
"""

import csv
import math
import os
import subprocess
import sys

from check_quick_bench import bench_test_args, check, failures  # the same reporting: a FAIL line per check, all counted


def main():
    args = bench_test_args()
    common = [args.manylights, "bench", "--scene", "boxes", "--size", "160x90", "--lights", "16", "--warmup", "0",
              "--timed-frames", "1", "--out", args.out]
    run = subprocess.run(common + ["--method", "naive,forward-plus,deferred", "--msaa", "1,4",
                                   "--reference", "supersampled:2", "--name", "aa"], capture_output=True, text=True)
    check(run.returncode == 0, "bench failed (%d):\n%s" % (run.returncode, run.stderr))
    with open(os.path.join(args.out, "aa.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    check(len(rows) == 5, "expected 5 points (naive and forward-plus x MSAA 1, 4; deferred once), got %d" % len(rows))
    for r in rows:
        label = "%s msaa %s" % (r["method"], r["msaa"])
        for column in ("aa_rmse", "aa_psnr_db"):
            value = r.get(column, "")
            check(value not in ("", None) and math.isfinite(float(value)), "%s: %s is %r" % (label, column, value))
        check(r.get("aa_reference") == "supersampled:2", "%s: aa_reference is %r" % (label, r.get("aa_reference")))
        check(r["reference"] in ("naive", "self"), "%s: the naive reference is missing (%r)" % (label, r["reference"]))
    by = {(r["method"], r["msaa"]): r for r in rows}
    for method in ("naive", "forward-plus"):
        one, four = by.get((method, "1")), by.get((method, "4"))
        if check(one and four, "%s lacks MSAA 1 or 4" % method):
            check(float(four["aa_rmse"]) < float(one["aa_rmse"]),
                  "%s: MSAA 4 (rmse %s) is not closer to the supersampled reference than MSAA 1 (%s)"
                  % (method, four["aa_rmse"], one["aa_rmse"]))
            check(float(four["pass_msaa_resolve_ms"] or "nan") >= 0, "%s MSAA 4: no msaa.resolve pass column" % method)
    deferred = [r for r in rows if r["method"] == "deferred"]
    check(len(deferred) == 1 and deferred[0]["msaa"] == "", "deferred should run once, with no msaa value")

    refused = subprocess.run(common + ["--method", "deferred", "--msaa", "4", "--name", "refused"], capture_output=True,
                             text=True)
    check(refused.returncode != 0, "bench took --msaa 4 for deferred alone")
    check(len(refused.stderr.strip().splitlines()) == 1 and "one sample per pixel" in refused.stderr,
          "the refusal should be one line saying why:\n" + refused.stderr)

    plot = subprocess.run([sys.executable, args.plot, os.path.join(args.out, "aa.csv"), "--only", "time_vs_aliasing"],
                          capture_output=True, text=True)
    check(plot.returncode == 0, "tools/plot failed:\n" + plot.stdout + plot.stderr)
    chart = os.path.join(args.out, "aa_time_vs_aliasing.png")
    check(os.path.exists(chart) and os.path.getsize(chart) > 10000, "the time_vs_aliasing chart is missing or empty")
    if failures:
        sys.exit("%d check(s) failed" % len(failures))
    print("aa bench: %d points, every check passed" % len(rows))


if __name__ == "__main__":
    main()
