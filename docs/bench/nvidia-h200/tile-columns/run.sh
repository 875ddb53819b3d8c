#!/usr/bin/env bash
# Issue 30: the compute raster's tile pass a column of pixels an invocation (its edges stepped
# down the column), its binning's tile test one corner an edge; and two changes to the list
# rounds of the lighting and the glass, measured and not kept. Against main, on an H200
# (nvidia-h200). Builds, each call's in one archive .devbin-tc<N>.txz with .devbin-lib and the gas
# station (.corpus-glass/), carried with .gl alone:
#   .devbin-main/      before: main at 61cf7a5
#   .devbin-rows4/     the tile pass 4 rows an invocation (ML_RASTER_TILE_ROWS) and the binning's
#                      test: what main now holds
#   .devbin-rows2/     the same, 2 rows;  .devbin-rows8/  8 rows
#   .devbin-boxes/     rows4 and the list rounds' box and marks per 32 invocations (boxes.patch)
#   .devbin-oneround/  rows4 and a probe: the lighting serves each tile's first list alone, the
#                      other lists' points left unlit (oneround.patch; its frames are wrong)
#   .devbin-merge/     rows4 and a round serving a tile's two smallest keys, their lists merged, one
#                      box for both (not committed: merge.patch's first form)
#   .devbin-merge2/    the same, each list with its own box and marks (merge.patch)
# Calls (steps: ../record-steps.sh), each after `warm`:
#   1  BUILDS='main rows4 rows2 boxes'     round 1, frames (rows4, then boxes), round 2
#   2  BUILDS='main rows4 rows8 oneround'  round 3, sponza 1, frames (rows8), round 4, sponza 2, round 5
#      (after four calls that carried Sponza in quarters into /root/.corpus-sponza)
#   3  BUILDS='main rows4 merge'           round 6, frames (merge), round 7, round 8, targets-4m
#   4  BUILDS='main rows4 merge2'          round 9, frames (merge2), round 10, round 11, targets-4m
#   5  BUILDS='main rows4'                 headline, round 12
S=docs/bench/nvidia-h200/tile-columns
BUILDS=${BUILDS:-'main:.devbin-main rows4:.devbin-rows4'}
NEW=${NEW:-.devbin-rows4}
HEADLINE=${HEADLINE:-rows4:.devbin-rows4}
. docs/bench/nvidia-h200/record-steps.sh "$@"
