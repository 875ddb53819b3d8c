#!/usr/bin/python3
"""`manylights bench --preset quick` as CI runs it on llvmpipe, then `tools/plot` on its CSV.

Checks what a reader of the results relies on: every required column, a row for every method,
positive times, exact methods within 50 dB PSNR of naive, capped lists that drop lights showing
it, the JSON record of the machine and the commit, and charts that are real pictures. Also: a
bad flag is refused in one line, and Ctrl-C keeps the points already measured. Asserts no timing.

    check_quick_bench.py --manylights BIN --plot tools/plot --out DIR
"""

import argparse
import csv
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import time

REQUIRED = ["method", "lights", "radius", "width", "height", "tiles_x", "tiles_y", "slices", "slicing", "assign",
            "gbuffer", "resolve", "workgroup", "frame_ms", "frame_ms_p10", "frame_ms_p90", "max_abs_err", "rmse",
            "psnr_db", "bad_pixel_share", "dropped_lights", "renderer", "sm_clock_mhz", "sm_clock_mhz_min"]
CHARTS = ["frame_time_vs_lights", "time_vs_error", "pass_breakdown", "workgroup", "tiles_by_cap", "cluster_occupancy",
          "slicing", "memory"]

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL: " + message)
    return condition


def num(text):
    return float(text) if text not in ("", None) else None


def check_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    check(len(rows) > 0, "the CSV has no rows")
    if not rows:
        return rows
    missing = [c for c in REQUIRED if c not in rows[0]]
    check(not missing, "missing columns: %s" % ", ".join(missing))
    passes = [c for c in rows[0] if c.startswith("pass_") and c.endswith("_ms")]
    check(len(passes) >= 5, "expected per-pass columns pass_<name>_ms, found %s" % passes)
    for method in ("naive", "forward-plus", "deferred"):
        check(any(r["method"] == method for r in rows), "no row for method %s" % method)
    errors = [r for r in rows if "error" in r.get("note", "")]
    check(not errors, "points failed: %s" % "; ".join("%s: %s" % (r["point"], r["note"]) for r in errors))

    timed = [r for r in rows if num(r["frame_ms"]) is not None]
    check(len(timed) == len(rows), "%d rows have no frame time" % (len(rows) - len(timed)))
    for r in timed:
        p10, med, p90 = num(r["frame_ms_p10"]), num(r["frame_ms"]), num(r["frame_ms_p90"])
        check(0 < p10 <= med <= p90, "point %s: frame times not positive and ordered: p10 %s, median %s, p90 %s"
              % (r["point"], p10, med, p90))
        pass_sum = sum(num(r[c]) or 0.0 for c in passes)
        check(pass_sum > 0, "point %s: no pass time" % r["point"])
        check(r["renderer"] != "", "point %s: empty renderer" % r["point"])
        for column in ("sm_clock_mhz", "sm_clock_mhz_min"):
            check(r[column] == "", "point %s: an SM clock (%s: %s) on llvmpipe, which has no NVIDIA clock"
                  % (r["point"], column, r[column]))
        check(int(r["width"]) > 0 and int(r["height"]) > 0 and num(r["radius"]) > 0, "point %s: bad size or radius" % r["point"])

    # Accuracy: exact methods match naive; capped lists that drop light references do not.
    exact = [r for r in timed if r["method"] == "naive" or r["assign"] == "exact"]
    with_ref = [r for r in exact if r["psnr_db"] != ""]
    check(len(with_ref) >= 10, "only %d exact points have accuracy numbers" % len(with_ref))
    for r in with_ref:
        psnr = math.inf if r["psnr_db"] == "inf" else float(r["psnr_db"])
        check(psnr >= 50.0, "point %s (%s, %s lights): PSNR %.1f dB < 50 against naive" % (r["point"], r["method"],
                                                                                          r["lights"], psnr))
        check(int(float(r["dropped_lights"])) == 0, "point %s: exact lists dropped lights" % r["point"])
    naive = [r for r in timed if r["method"] == "naive"]
    check(all(r["psnr_db"] == "inf" and num(r["max_abs_err"]) == 0 for r in naive),
          "naive must be identical to its own reference")
    capped = [r for r in timed if r["assign"] == "capped"]
    check(len(capped) > 0, "no capped points")
    dropping = [r for r in capped if int(float(r["dropped_lights"])) > 0]
    check(len(dropping) > 0, "no capped point dropped lights (the quick preset's cap of 4 should)")
    for r in dropping:
        check(r["psnr_db"] != "inf" and float(r["psnr_db"]) < 50.0,
              "point %s drops %s light references yet matches naive (PSNR %s)" % (r["point"], r["dropped_lights"],
                                                                                r["psnr_db"]))
    # Where naive cannot be afforded, the row says so instead of giving numbers.
    skipped = [r for r in timed if r["psnr_db"] == ""]
    check(all("no naive reference" in r["note"] for r in skipped), "a point lacks accuracy numbers without a note")
    clustered = [r for r in timed if r["method"] != "naive"]
    check(all(num(r["clusters"]) and 0.0 <= num(r["empty_share"]) <= 1.0 and num(r["max_lights_per_cluster"]) >= 1
              for r in clustered), "clustered points need cluster statistics")
    check(all(num(r["gbuffer_bytes"]) > 0 for r in clustered if r["method"] == "deferred"),
          "deferred points must report G-buffer memory")
    return rows


def check_json(path, rows):
    with open(path) as f:
        record = json.load(f)
    machine, build = record.get("machine", {}), record.get("build", {})
    check(machine.get("gl_renderer"), "the JSON lacks machine.gl_renderer")
    check(machine.get("gl_version"), "the JSON lacks machine.gl_version")
    check(machine.get("cpu"), "the JSON lacks machine.cpu")
    check(build.get("commit"), "the JSON lacks build.commit")
    check(record.get("status") == "complete", "status %r, expected complete" % record.get("status"))
    points = record.get("points", {})
    check(points.get("planned") == points.get("measured") == len(rows),
          "points planned %s, measured %s, CSV rows %d" % (points.get("planned"), points.get("measured"), len(rows)))
    check(len(record.get("rows", [])) == len(rows), "the JSON's rows differ from the CSV's")
    check(record.get("sweep_document", {}).get("name") == "quick", "the JSON lacks the sweep document")


def check_png(path):
    """A real picture: PNG, a sensible size, and more than one colour in it."""
    import matplotlib.image
    if not check(os.path.exists(path), "missing chart %s" % path):
        return
    with open(path, "rb") as f:
        check(f.read(8) == b"\x89PNG\r\n\x1a\n", "%s is not a PNG" % path)
    check(os.path.getsize(path) > 20000, "%s is suspiciously small (%d bytes)" % (path, os.path.getsize(path)))
    image = matplotlib.image.imread(path)
    h, w = image.shape[:2]
    check(w >= 600 and h >= 400, "%s is %dx%d" % (path, w, h))
    flat = image[..., :3].reshape(-1, 3)
    check(float(flat.std()) > 0.05, "%s is nearly blank" % path)
    svg = path[:-4] + ".svg"
    check(os.path.exists(svg) and os.path.getsize(svg) > 5000, "missing or empty %s" % svg)


def check_bad_flag(manylights):
    run = subprocess.run([manylights, "bench", "--lights", "64,-5", "--dry-run"], capture_output=True, text=True)
    lines = [l for l in run.stderr.splitlines() if l.strip()]
    check(run.returncode != 0, "a negative light count was accepted")
    check(len(lines) == 1 and "--lights" in lines[0] and "-5" in lines[0],
          "expected one line naming --lights and -5, got: %r" % run.stderr)


def check_camera_set(manylights):
    """--camera atrium-set expands to the four cameras of the set, in order; atrium-above to its two."""
    run = subprocess.run([manylights, "bench", "--method", "deferred", "--camera", "atrium-set", "--print-sweep"],
                         capture_output=True, text=True)
    check(run.returncode == 0, "bench --camera atrium-set --print-sweep exited %d: %s" % (run.returncode, run.stderr))
    run = subprocess.run([manylights, "bench", "--method", "deferred", "--camera", "atrium-set", "--dry-run"],
                         capture_output=True, text=True)
    text = run.stdout + run.stderr
    for camera in ("-15,1.7,-6.3,15,1.7,-6.3,60", "0,28,0.5,0,0,0,60", "-16,3,-4.5,16,1.5,4.5,60"):
        check(camera in text, "bench --camera atrium-set --dry-run does not list camera %s: %r" % (camera, text[-2000:]))
    run = subprocess.run([manylights, "bench", "--method", "deferred", "--camera", "atrium-above", "--dry-run"],
                         capture_output=True, text=True)
    text = run.stdout + run.stderr
    check(run.returncode == 0, "bench --camera atrium-above --dry-run exited %d: %s" % (run.returncode, run.stderr))
    for camera in ("0,14,0.5,0,0,0,90", "0,11,0.5,0,0,0,100"):
        check(camera in text, "bench --camera atrium-above --dry-run does not list camera %s: %r" % (camera, text[-2000:]))


def check_interrupt(manylights, out):
    """Ctrl-C after the first point: exit 130, and the CSV and JSON keep what was measured."""
    directory = os.path.join(out, "interrupted")
    shutil.rmtree(directory, ignore_errors=True)
    proc = subprocess.Popen([manylights, "bench", "--method", "forward-plus", "--lights", "4,8,16,32,64,128",
                             "--size", "64x36", "--warmup", "0", "--timed-frames", "2", "--out", directory],
                            stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True)
    for line in proc.stderr:
        if line.startswith("bench [1/"):
            proc.send_signal(signal.SIGINT)
            break
    proc.stderr.read()
    code = proc.wait(timeout=120)
    check(code == 130, "interrupted bench exited %s, expected 130" % code)
    with open(os.path.join(directory, "sweep.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(directory, "sweep.json")) as f:
        record = json.load(f)
    check(1 <= len(rows) < 6, "interrupted run kept %d of 6 points" % len(rows))
    check(record.get("status") == "interrupted", "interrupted run's status is %r" % record.get("status"))


def bench_test_args():
    """The arguments every bench check takes (the executable, tools/plot, an output directory,
    emptied here)."""
    parser = argparse.ArgumentParser()
    parser.add_argument("--manylights", required=True)
    parser.add_argument("--plot", required=True)
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    shutil.rmtree(args.out, ignore_errors=True)
    os.makedirs(args.out)
    return args


def main():
    args = bench_test_args()

    check_bad_flag(args.manylights)
    check_camera_set(args.manylights)

    start = time.monotonic()
    run = subprocess.run([args.manylights, "bench", "--preset", "quick", "--out", args.out], capture_output=True, text=True)
    print(run.stderr[-3000:])
    print("bench --preset quick took %.1f s (not asserted)" % (time.monotonic() - start))
    if not check(run.returncode == 0, "bench exited %d" % run.returncode):
        return 1
    rows = check_csv(os.path.join(args.out, "quick.csv"))
    check_json(os.path.join(args.out, "quick.json"), rows)

    charts = os.path.join(args.out, "charts")
    plot = subprocess.run([sys.executable, args.plot, os.path.join(args.out, "quick.csv"), "--out", charts],
                          capture_output=True, text=True)
    print(plot.stdout + plot.stderr)
    check(plot.returncode == 0, "tools/plot exited %d" % plot.returncode)
    for name in CHARTS:
        check_png(os.path.join(charts, "quick_" + name + ".png"))

    check_interrupt(args.manylights, args.out)

    if failures:
        print("%d check(s) failed; outputs in %s" % (len(failures), args.out))
        return 1
    print("all checks passed; outputs in %s" % args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
