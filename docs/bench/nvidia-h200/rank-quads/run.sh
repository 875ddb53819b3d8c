#!/usr/bin/env bash
# Issue 30 (not kept): the list sort's rank sort reading four entries a shared-memory load
# (rank-quads.patch on ec5eb59), against main, on an H200 (nvidia-h200). Builds and the gas
# station (.corpus-glass/) in .devbin-rk.txz, carried with .gl alone (the tree had grown):
#   .devbin-steps/   before: main at ec5eb59 (the fewer-steps record's `nocopy` build, the same code)
#   .devbin-r128/    the rank sort over uvec4 reads, lists up to 128 entries (ML_SORT_RANK_MAX), as before
#   .devbin-r256/    the same up to 256 entries: every short list by rank, none by the bitonic network
# Steps: ../record-steps.sh; the command ran `warm`, `round 1`, `sponza 1`, `round 2`, `sponza 2`,
# `targets-4m`, `frames` after three calls that carry Sponza in parts (.sponza-part1..3, each
# copied into /root/.corpus-sponza/corpus/amd/sponza; two halves no longer fitted the carry).
S=docs/bench/nvidia-h200/fewer-steps
BUILDS=${BUILDS:-'steps:.devbin-steps r128:.devbin-r128 r256:.devbin-r256'}
NEW=${NEW:-.devbin-r128}
HEADLINE=${HEADLINE:-r128:.devbin-r128}
. docs/bench/nvidia-h200/record-steps.sh "$@"
