#!/usr/bin/env bash
# Issue 30: (1) the tile pass reads the pair list only up to the pairs written (the list's end
# lowered to the first triangle whose pairs did not fit), never a slot an earlier frame left;
# (2) the compute raster's store is not reset between frames: every other frame inverts its words
# and resolves by atomicMax, and the finish empties only the pixels a frame left, where it wrote
# every pixel's 8 bytes. Against main before both, on an H200 (nvidia-h200). Builds, in one
# archive .devbin-sf.txz with .devbin-lib, carried with .gl, .corpus-glass
# (corpus/amd/gas_station) and Sponza's four parts (.sponza-part0..3; docs/bench moved out of the
# tree but for the files the call reads, so that the tree and Sponza fit 64 MiB together):
#   .devbin-m877/       before: main at 877e719
#   .devbin-overflow/   (1) alone: main at bae12d0
#   .devbin-flip/       (1) and (2): explore/store-flip
#   .devbin-tests/      the GPU tests of (1) and (2) (ml_gpu_tests): the compute raster's against
#                       the hardware raster's ids with the H200's 64-bit atomics
# The call (call/): warm, round 1, frames, tests, sponza 1, round 2.
S=docs/bench/nvidia-h200/store-flip
BUILDS=${BUILDS:-'main:.devbin-m877 overflow:.devbin-overflow flip:.devbin-flip'}
NEW=${NEW:-.devbin-flip}
HEADLINE=${HEADLINE:-flip:.devbin-flip}
TESTS=${TESTS:-'ComputeRaster*'}
. docs/bench/nvidia-h200/record-steps.sh "$@"
