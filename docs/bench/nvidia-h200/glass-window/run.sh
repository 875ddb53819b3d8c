#!/usr/bin/env bash
# Issue 30: the glass's capture over a window of whole screen tiles around its projected bounds
# (its clear, scan and shading's tiles), and fitted slicing's depth range reduced by the compute
# raster's finish (cluster.depth-range reads no depth); then the capture's depth test made in its
# shader against the compute raster's depth (no copy into the depth buffer), and the range sliced
# by cluster.bounds (no pass of one invocation). Against main, on an H200 (nvidia-h200). Builds,
# each call's in one archive .devbin-gw<N>.txz with .devbin-lib and the gas station
# (.corpus-glass/), carried with .gl alone:
#   .devbin-main/   before: main at ee0ad66
#   .devbin-win/    the window and the finish's range (e1f6e41)
#   .devbin-ab/     win, the capture's own depth test and the slicing in cluster.bounds (543a5f8)
# Calls (steps: ../record-steps.sh), each after four that carried Sponza in quarters into
# /root/.corpus-sponza, and `warm`:
#   1  BUILDS='main win'     round 1, frames, sponza 1, targets-4m, headline, round 2
#   2  BUILDS='main win ab'  round 3, frames (ab), sponza 2, targets-4m, headline (ab), round 4
S=docs/bench/nvidia-h200/glass-window
BUILDS=${BUILDS:-'main:.devbin-main win:.devbin-win'}
NEW=${NEW:-.devbin-win}
HEADLINE=${HEADLINE:-win:.devbin-win}
. docs/bench/nvidia-h200/record-steps.sh "$@"
