#!/usr/bin/env python3
"""Issue 62's chart: frame time with and without shadow rays per camera (the visibility buffer,
65,536 lights, 2560x1440, H100), and the shadow rays a second each implies. Reads shadows-b.csv
(the second of the two identical runs; the first agrees within 1 %)."""
import csv
import os
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

here = os.path.dirname(os.path.abspath(__file__))
rows = [r for r in csv.DictReader(open(os.path.join(here, "shadows-b.csv"))) if r["frame_ms"]]
names = {"default": "default", "gltf:0": "gltf:0", "gltf:1": "gltf:1", "gltf:2": "gltf:2", "gltf:3": "gltf:3"}
points = []
for r in rows:
    if r["method"] != "visibility" or r["experiment"] not in ("atrium-64k", "sponza-64k"):
        continue
    scene = "atrium" if r["experiment"] == "atrium-64k" else "Sponza"
    label = f"{scene}\n{names.get(r['camera'], r['camera'].split(',')[0] + ',...')}"
    points.append((label, r["shadows"], float(r["frame_ms"]), r["shadow_grays_per_s"]))
labels = list(dict.fromkeys(p[0] for p in points))
off = [next(p[2] for p in points if p[0] == l and p[1] == "off") for l in labels]
rays = [next(p[2] for p in points if p[0] == l and p[1] == "rays") for l in labels]
rate = [float(next(p[3] for p in points if p[0] == l and p[1] == "rays")) for l in labels]

fig, (a, b) = plt.subplots(1, 2, figsize=(13, 4.8))
x = range(len(labels))
a.bar([i - 0.2 for i in x], off, 0.4, label="--shadows off")
a.bar([i + 0.2 for i in x], rays, 0.4, label="--shadows rays")
a.axhline(12, color="grey", ls="--", lw=0.8)
a.text(len(labels) - 0.5, 12, "atrium target 12 ms", ha="right", va="bottom", fontsize=8)
a.axhline(20, color="grey", ls=":", lw=0.8)
a.text(len(labels) - 0.5, 20, "Sponza target 20 ms", ha="right", va="bottom", fontsize=8)
a.set_xticks(list(x), labels, fontsize=7)
a.set_ylabel("frame time, ms (median of 30)")
a.set_title("Visibility buffer, 65,536 lights, overlap:32, 2560x1440")
a.legend()
b.bar(list(x), rate, 0.6, color="tab:green")
b.axhline(10, color="grey", ls="--", lw=0.8)
b.text(len(labels) - 0.5, 10, "goal: 10 billion a second", ha="right", va="bottom", fontsize=8)
b.set_ylim(0, 11)
b.set_xticks(list(x), labels, fontsize=7)
b.set_ylabel("shadow rays a second, billions (rays / frame time)")
b.set_title("Rays per second (every pass's time counted)")
fig.suptitle("Exact shadow rays on an NVIDIA H100 80GB HBM3, SM clock 1980 MHz (issue 62, bef6c5d)")
fig.tight_layout()
fig.savefig(os.path.join(here, "shadow-rays-h100.png"), dpi=110)
