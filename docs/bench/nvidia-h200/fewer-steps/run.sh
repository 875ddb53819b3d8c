#!/usr/bin/env bash
# Issue 30: the light assignment, its sort and the glass's capture in fewer steps, against main,
# on an H200 (nvidia-h200). Builds:
#   .devbin-main/     before: main at 24ff92b
#   .devbin-assign/   the assignment's buffers cleared in one dispatch and no copy between its
#                     passes; the sort's dispatches written by its classification's last workgroup
#   .devbin-all/      and the glass's per-pixel counts scanned in blocks placed by an atomic
#   .devbin-nocopy/   and no buffer copy or upload left: each scan writes its total where it is
#                     read, the assignment's dispatch pass the candidates for the CPU, and the
#                     sort's classification leaves its counters at 0 for the next run
# The first call carried .devbin-fs.txz (main, assign, all) and ran `warm`, `round 1`, `frames`
# with BUILDS='main:.devbin-main assign:.devbin-assign all:.devbin-all' NEW=.devbin-all; the
# later ones .devbin-fs2.txz (main, all, nocopy) with the defaults below.
# Steps: ../record-steps.sh.
S=docs/bench/nvidia-h200/fewer-steps
BUILDS=${BUILDS:-'main:.devbin-main all:.devbin-all nocopy:.devbin-nocopy'}
NEW=${NEW:-.devbin-nocopy}
HEADLINE=${HEADLINE:-nocopy:.devbin-nocopy}
. docs/bench/nvidia-h200/record-steps.sh "$@"
