#!/usr/bin/env bash
# Issue 30: the glass's capture over a window of whole screen tiles around its projected bounds
# (its clear, scan and shading's tiles), and fitted slicing's depth range reduced by the compute
# raster's finish (cluster.depth-range reads no depth). Against main, on an H200 (nvidia-h200).
# Builds, in one archive .devbin-gw.txz with .devbin-lib and the gas station (.corpus-glass/),
# carried with .gl alone:
#   .devbin-main/   before: main at ee0ad66
#   .devbin-win/    the change (e1f6e41)
# Calls (steps: ../record-steps.sh), after four that carried Sponza in quarters into
# /root/.corpus-sponza:
#   1  warm, round 1, frames, sponza 1, round 2, targets-4m, headline
S=docs/bench/nvidia-h200/glass-window
BUILDS=${BUILDS:-'main:.devbin-main win:.devbin-win'}
NEW=${NEW:-.devbin-win}
HEADLINE=${HEADLINE:-win:.devbin-win}
. docs/bench/nvidia-h200/record-steps.sh "$@"
