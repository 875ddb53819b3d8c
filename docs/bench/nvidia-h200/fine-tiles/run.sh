#!/usr/bin/env bash
# Issue 30: the compute raster's large triangles of small bounds binned to 8x8 tiles
# (ML_RASTER_FINE_EXTENT 128), and the exposure reduction over 64x64 tiles, 16 pixels an
# invocation. Against main, on an H200 (nvidia-h200). Builds, in one archive .devbin-ft.txz with
# .devbin-lib, carried with .gl, .corpus-glass (corpus/amd/gas_station) and Sponza's four parts
# (.sponza-part0..3, unpacked into /root/.corpus-sponza; the call ran with docs/bench moved out
# of the tree but for the files it reads, so that the tree and Sponza fit the device tool's
# 64 MiB together):
#   .devbin-main/   before: main at 09de9b4
#   .devbin-fin/    after: 76d5037
#   .devbin-fin2/   after, with the exposure in one dispatch: 596078c (second call)
# First call (steps: ../record-steps.sh): warm, round 1, frames, sponza 1, targets-4m, headline,
# round 2, sponza 2. Second call (files in call2/): warm; sponza 3 with
# BUILDS='main:.devbin-main fin:.devbin-fin fin2:.devbin-fin2'; round 3 and frames with
# BUILDS='main:.devbin-main fin2:.devbin-fin2' NEW=.devbin-fin2; sponza 4 as sponza 3.
# explore/ holds the two calls that chose the thresholds (explore/README.md).
S=docs/bench/nvidia-h200/fine-tiles
BUILDS=${BUILDS:-'main:.devbin-main fin:.devbin-fin'}
NEW=${NEW:-.devbin-fin}
HEADLINE=${HEADLINE:-fin:.devbin-fin}
if [ "${1:-}" = sponza ] && [ ! -d /root/.corpus-sponza ]; then
  mkdir -p /root/.corpus-sponza && cat .sponza-part0 .sponza-part1 .sponza-part2 .sponza-part3 | tar x -C /root/.corpus-sponza
fi
. docs/bench/nvidia-h200/record-steps.sh "$@"
