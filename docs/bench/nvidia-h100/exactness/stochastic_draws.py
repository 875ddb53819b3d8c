#!/usr/bin/env python3
"""Issue 29's million-light anomaly: the mean of 8 stochastic draws came out further from the
physical image than one draw on the H100, and the methods disagreed. Given PFMs of
`render --accumulate K` for K = 1..N per method (DIR/METHOD-K.pfm), rebuilds each draw
(draw k = K*mean_K - (K-1)*mean_{K-1}) and prints, per draw, each method's largest value and the
largest difference between methods, with the pixel. Standard library only.

    stochastic_draws.py DIR N METHOD...
"""
import array
import sys


def read_pfm(path):
    with open(path, "rb") as f:
        kind = f.readline().strip()
        width, height = map(int, f.readline().split())
        scale = float(f.readline())
        data = array.array("f")
        data.frombytes(f.read())
    if scale > 0:
        data.byteswap()
    return width, height, 3 if kind == b"PF" else 1, data


def main():
    folder, n, methods = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
    means = {m: [read_pfm(f"{folder}/{m}-{k}.pfm") for k in range(1, n + 1)] for m in methods}
    width, _, channels, _ = means[methods[0]][0]
    draws = {}
    for m in methods:
        draws[m] = []
        for k in range(n):
            cur = means[m][k][3]
            if k == 0:
                draws[m].append(cur)
                continue
            prev = means[m][k - 1][3]
            draws[m].append(array.array("f", ((k + 1) * a - k * b for a, b in zip(cur, prev))))
    for k in range(n):
        line = [f"draw {k}:"]
        for m in methods:
            d = draws[m][k]
            i = max(range(len(d)), key=d.__getitem__)
            line.append(f"{m} max {d[i]:.4g} at ({i // channels % width},{i // channels // width})")
        ref = draws[methods[0]][k]
        for m in methods[1:]:
            d = draws[m][k]
            diffs = [abs(a - b) for a, b in zip(d, ref)]
            i = max(range(len(diffs)), key=diffs.__getitem__)
            bad = sum(1 for x in diffs if x > 1e-2)
            line.append(f"|{m}-{methods[0]}| max {diffs[i]:.4g} at ({i // channels % width},{i // channels // width}) "
                        f"[{ref[i]:.4g} vs {d[i]:.4g}], {bad} values off by more than 0.01")
        print("  ".join(line))
    for m in methods:
        last = means[m][n - 1][3]
        i = max(range(len(last)), key=last.__getitem__)
        print(f"mean of {n}, {m}: max {last[i]:.4g} at ({i // channels % width},{i // channels // width})")


if __name__ == "__main__":
    main()
