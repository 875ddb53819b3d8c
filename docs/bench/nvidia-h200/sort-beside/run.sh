#!/usr/bin/env bash
# Issue 30: the list sort's long lists spread over a workgroup per chunk (and a merge dispatch,
# a workgroup per chunk again), and the visibility resolve's dispatches beside the assignment's
# count pass. Against main, on an H200 (nvidia-h200). Builds, in one archive .devbin-sb.txz with
# .devbin-lib and the gas station (.corpus-glass/), carried with .gl alone:
#   .devbin-main/   before: main at 76aaaeb
#   .devbin-fin/    after: 67b28c1
# Calls (steps: ../record-steps.sh): warm, round 1, frames, targets-4m, headline, round 2; then,
# after four calls that carried Sponza in parts (.sponza-part0..3, concatenated and unpacked into
# /root/.corpus-sponza), warm, sponza 1, sponza 2 (files in sponza/).
# explore/ holds the two calls that chose the change (explore/README.md).
S=docs/bench/nvidia-h200/sort-beside
BUILDS=${BUILDS:-'main:.devbin-main fin:.devbin-fin'}
NEW=${NEW:-.devbin-fin}
HEADLINE=${HEADLINE:-fin:.devbin-fin}
. docs/bench/nvidia-h200/record-steps.sh "$@"
