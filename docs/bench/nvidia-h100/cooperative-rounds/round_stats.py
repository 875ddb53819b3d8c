#!/usr/bin/env python3
"""Summarise the per-workgroup counters experiments.patch writes (ML_ROUND_STATS=<file>): for the
opaque lighting (words from 0) and the glass (words from 2^20), 8 words per workgroup of an
8x8-pixel tile: rounds, batches staged, points served, the sum over rounds of the longest served
invocation's pairs, pairs, lights staged, warp iterations, and the serial chain a cooperative round
(at most 24 served points) would leave. Usage: round_stats.py FILE WORKGROUPS (57600 at 2560x1440)."""
import sys
import numpy as np

words = np.fromfile(sys.argv[1], dtype=np.uint32).reshape(-1, 8).astype(np.int64)
groups = int(sys.argv[2])
for name, part in (("opaque", words[:groups]), ("glass", words[(1 << 20) // 8:(1 << 20) // 8 + groups])):
    act = part[part[:, 2] > 0]
    rounds, batches, served, chain_pairs, pairs, staged, warp_iterations, coop = (act[:, i] for i in range(8))
    chain = batches + chain_pairs
    coop_chain = batches + coop
    print(f"{name}: {len(act)} workgroups with work, {rounds.sum()} rounds ({rounds.mean():.2f} a workgroup, max {rounds.max()}), "
          f"{served.sum()} points served ({served.sum() / rounds.sum():.1f} a round), {batches.sum()} batches, "
          f"{staged.sum()} lights staged, {pairs.sum()} pairs ({pairs.sum() / served.sum():.1f} a point), "
          f"{warp_iterations.sum()} warp iterations ({pairs.sum() / warp_iterations.sum():.1f} lanes each)")
    print(f"  serial chain (batches + the longest invocation's pairs, per workgroup): sum {chain.sum()}, "
          f"mean {chain.mean():.0f}, p99 {np.percentile(chain, 99):.0f}, max {chain.max()}; "
          f"cooperative at <= 24 points: sum {coop_chain.sum()}, p99 {np.percentile(coop_chain, 99):.0f}, max {coop_chain.max()}")
