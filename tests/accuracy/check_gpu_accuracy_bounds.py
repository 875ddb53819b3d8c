#!/usr/bin/python3
"""Tests tools/gpu-accuracy's check (issue 23): a row of a GPU accuracy record passes inside the
contract (at most 0.01 % of pixels more than 1/255 off naive) or inside the bound of a known
exception, and fails otherwise, one line per violation; a bound no row needs fails as stale; a
bounds file naming an unexplained cause is refused; --propose-bounds re-derives bounds by the
margin rule without writing anything. Synthetic records and bounds, through the tool's own
--check mode; then the committed bounds file's causes lead to headings of the docs.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

FIELDS = ["file", "camera", "method", "gbuffer", "max_err_255", "share_over_1_255", "ldr_psnr_db", "psnr_db",
          "holds_contract", "note"]
CAUSE_LINK = "docs/accuracy-and-stability.md#g-buffer-precision-on-glossy-normal-mapped-surfaces"
BOUNDS = {
    "brdf": "blinn-phong",
    "causes": {"gbuffer-precision": CAUSE_LINK},
    "exceptions": [{"file": "Glossy", "methods": ["deferred"], "layouts": ["packed"], "cause": "gbuffer-precision",
                    "max_share_over_1_255": 0.01, "max_err_255": 20}],
}

failures = []


def row(file, method, gbuffer, share, max_err, camera="default"):
    return {"file": file, "camera": camera, "method": method, "gbuffer": gbuffer, "max_err_255": max_err,
            "share_over_1_255": share, "ldr_psnr_db": "60", "psnr_db": "80", "holds_contract": "", "note": ""}


def good_rows():
    return [row("Glossy", "deferred", "packed", "0.005", "10"),
            row("Glossy", "deferred", "packed", "0.00002", "2", camera="gltf:0"),
            row("Glossy", "forward-plus", "", "0", "1"),
            row("Plain", "deferred", "packed", "0.0001", "3"),
            row("Plain", "visibility", "standard", "0", "1")]


def run_check(tool, work, rows, bounds, *extra):
    csv_path, bounds_path = os.path.join(work, "accuracy.csv"), os.path.join(work, "bounds.json")
    with open(csv_path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)
    with open(bounds_path, "w") as f:
        json.dump(bounds, f)
    result = subprocess.run([sys.executable, tool, "--check", csv_path, "--bounds", bounds_path, *extra],
                            capture_output=True, text=True)
    return result.returncode, result.stdout + result.stderr


def expect(name, outcome, rc, *lines):
    got_rc, out = outcome
    missing = [line for line in lines if line not in out]
    if got_rc != rc or missing:
        failures.append(name)
        print(f"FAIL: {name}: exit {got_rc} (expected {rc}); missing {missing}\n{out}")
    else:
        print(f"ok: {name}")


def with_row(index, **changes):
    rows = good_rows()
    rows[index] = dict(rows[index], **changes)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", required=True)
    parser.add_argument("--work", required=True)
    args = parser.parse_args()
    tool = os.path.join(args.root, "tools", "gpu-accuracy")
    os.makedirs(args.work, exist_ok=True)
    with tempfile.TemporaryDirectory(dir=args.work) as work:
        check = lambda rows, bounds=BOUNDS, *extra: run_check(tool, work, rows, bounds, *extra)

        expect("in the contract or in its bound: passes", check(good_rows()), 0, "0 violations",
               "Glossy deferred packed [gbuffer-precision]: worst 0.5 % (default), max 10/255; bound 1 %, 20/255")
        expect("over the bound's share: fails", check(with_row(0, share_over_1_255="0.02")), 1,
               "VIOLATION: Glossy default deferred packed: 2 % of pixels over 1/255 (bound 1 %), "
               "max 10/255 (bound 20/255) [gbuffer-precision]")
        expect("over the bound's max error: fails", check(with_row(0, max_err_255="21")), 1,
               "VIOLATION: Glossy default deferred packed: 0.5 % of pixels over 1/255 (bound 1 %), "
               "max 21/255 (bound 20/255)")
        expect("outside the contract, no exception: fails", check(with_row(3, share_over_1_255="0.0002")), 1,
               "VIOLATION: Plain default deferred packed: 0.02 % of pixels over 1/255, max 3/255; "
               "outside the contract (0.01 %) and no exception covers it")
        expect("another layout than the exception's: fails",
               check(good_rows() + [row("Glossy", "deferred", "standard", "0.005", "10")]), 1,
               "VIOLATION: Glossy default deferred standard: 0.5 % of pixels over 1/255")
        expect("a bound no row needs: stale", check(with_row(0, share_over_1_255="0.0001")), 1,
               "VIOLATION: Glossy deferred packed [gbuffer-precision]: stale bound")
        expect("a bound no row was measured for: fails", check(good_rows()[3:]), 1,
               "VIOLATION: Glossy deferred packed [gbuffer-precision]: no row of the record is a frame it covers")
        expect("a row with no measurement: fails", check(with_row(4, share_over_1_255="", note="error: boom")), 1,
               "VIOLATION: Plain default visibility standard: no measurement (error: boom)")
        unexplained = json.loads(json.dumps(BOUNDS))
        unexplained["exceptions"][0]["cause"] = "UNEXPLAINED"
        expect("an unexplained cause: refused", check(good_rows(), unexplained), 1,
               "cause 'UNEXPLAINED' is not one of the causes the file explains")

        excusing_default = json.loads(json.dumps(BOUNDS))
        excusing_default["exceptions"][0]["layouts"] = ["packed", "exact"]
        expect("a bound on a method's default layout: refused", check(good_rows(), excusing_default), 1,
               "excuses a method's default settings (layout 'exact' or none)")

        rows = with_row(0, share_over_1_255="0.02", max_err_255="30") + [row("Other", "visibility", "packed", "0.001", "4")]
        rc, out = check(rows, BOUNDS, "--propose-bounds")
        with open(os.path.join(work, "bounds.json")) as f:
            on_disk = json.load(f)
        proposed = json.loads(out[:out.rindex("}") + 1])
        e = proposed["exceptions"]
        ok = (rc == 0 and on_disk == BOUNDS and len(e) == 2
              and e[0] == dict(BOUNDS["exceptions"][0], max_share_over_1_255=0.025, max_err_255=38)
              and e[1] == {"file": "Other", "methods": ["visibility"], "layouts": ["packed"], "cause": "UNEXPLAINED",
                           "max_share_over_1_255": 0.0013, "max_err_255": 6}
              and "margin" in proposed)
        expect("--propose-bounds: x 1.25 rounded up, the cause kept, a new one UNEXPLAINED, nothing written",
               (0 if ok else 1, out), 0)

    # The committed bounds: each cause leads to a heading of the docs, and the record sits beside.
    sys.path.insert(0, os.path.join(args.root, "tests", "docs"))
    from check_docs import anchors_of
    bounds_path = os.path.join(args.root, "docs", "bench", "nvidia-h100", "accuracy", "bounds.json")
    with open(bounds_path) as f:
        committed = json.load(f)
    for cause, link in committed["causes"].items():
        page, _, anchor = link.partition("#")
        page = os.path.join(args.root, page)
        if not os.path.exists(page) or anchor not in anchors_of(page):
            failures.append(f"cause {cause}")
            print(f"FAIL: bounds.json: cause {cause}: {link} is no heading of the docs")
    if not os.path.exists(os.path.join(os.path.dirname(bounds_path), committed["record"])):
        failures.append("record")
        print(f"FAIL: bounds.json: record {committed['record']} is not beside it")

    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
