#!/usr/bin/env bash
# Issue 30: the compute raster's tile pass takes ML_RASTER_TILE_PAIRS pairs a workgroup at a time,
# together (both triangles read, both pixels' coverage, then both stores) where all are 8x8 tiles.
# Against main, on an H200 (nvidia-h200). Builds, in one archive .devbin-tp.txz with .devbin-lib,
# carried with .gl, .corpus-glass (corpus/amd/gas_station) and Sponza's four parts
# (.sponza-part0..3; the call ran with docs/bench moved out of the tree but for the files it
# reads, so that the tree and Sponza fit the device tool's 64 MiB together):
#   .devbin-main/     before: main at d198f02
#   .devbin-pairs2/   two pairs at a time
#   .devbin-pairs4/   four pairs at a time (ML_RASTER_TILE_PAIRS 4)
S=docs/bench/nvidia-h200/tile-pairs
BUILDS=${BUILDS:-'main:.devbin-main pairs2:.devbin-pairs2 pairs4:.devbin-pairs4'}
NEW=${NEW:-.devbin-pairs2}
HEADLINE=${HEADLINE:-pairs2:.devbin-pairs2}
. docs/bench/nvidia-h200/record-steps.sh "$@"
