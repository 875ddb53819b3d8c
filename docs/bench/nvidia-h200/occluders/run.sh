#!/usr/bin/env bash
# Issue 30: occluders for the compute raster's binning (a large opaque triangle that covers all of
# an 8x8 tile's pixel centres marks the tile with its farthest depth; the binning lists no pair
# wholly behind the mark). Against main, on an H200 (nvidia-h200). Builds, in one archive
# .devbin-occ.txz with .devbin-lib, carried with .gl, .corpus-glass (corpus/amd/gas_station) and
# Sponza's four parts (.sponza-part0..3; the call ran with docs/bench moved out of the tree but for
# the files it reads, so that the tree and Sponza fit the device tool's 64 MiB together):
#   .devbin-main/   before: main at d198f02
#   .devbin-occ/    the occluders
S=docs/bench/nvidia-h200/occluders
BUILDS=${BUILDS:-'main:.devbin-main occ:.devbin-occ'}
NEW=${NEW:-.devbin-occ}
HEADLINE=${HEADLINE:-occ:.devbin-occ}
. docs/bench/nvidia-h200/record-steps.sh "$@"
