#!/usr/bin/env bash
# Issue 30: a large opaque triangle binned to at most ML_RASTER_SETUP_BIN_TILES 8x8 tiles lists
# its (triangle, tile) pairs in its own setup invocation; the binning's workgroup per triangle
# (two loops over its tiles, four barriers, an atomic) skips it. Against main, on an H200
# (nvidia-h200). Builds, in one archive .devbin-sb.txz with .devbin-lib, carried with .gl,
# .corpus-glass (corpus/amd/gas_station) and Sponza's four parts (.sponza-part0..3; the call ran
# with docs/bench moved out of the tree but for the files it reads, so that the tree and Sponza fit
# the device tool's 64 MiB together):
#   .devbin-main/     before: main at d198f02
#   .devbin-sbin64/   triangles of at most 64 8x8 tiles binned by their setup (kept)
# The call (call/): warm, round 1, frames, sponza 1, round 2, headline, sponza 2, round 3. A build
# binning every 8x8-tiled triangle in its setup (ML_RASTER_SETUP_BIN_TILES 289) was packed but
# not run: three refused calls had spent the session's GPU time.
S=docs/bench/nvidia-h200/setup-bin
BUILDS=${BUILDS:-'main:.devbin-main sbin64:.devbin-sbin64'}
NEW=${NEW:-.devbin-sbin64}
HEADLINE=${HEADLINE:-sbin64:.devbin-sbin64}
. docs/bench/nvidia-h200/record-steps.sh "$@"
