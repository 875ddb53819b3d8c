#!/usr/bin/env bash
# Issue 30, the same record's second part (not kept): two more steps off the clustering, against
# the first part's result, on an H200 (nvidia-h200). Builds in .devbin-fo.txz:
#   .devbin-steps/   before: the first part's `nocopy` build (main at ec5eb59, the same code)
#   .devbin-fold/    fold.patch on ec5eb59: the fitted slicing's range turned into slices by the
#                    reduction's last workgroup (a dispatch of one invocation before), and no
#                    barrier after the cluster bounds (the assignment's first barrier covers them)
# Steps: ../../record-steps.sh; this part's command ran `warm`, `round 1`, `frames`, `round 2`,
# `round 3`, `headline`.
S=docs/bench/nvidia-h200/fewer-steps
BUILDS=${BUILDS:-'steps:.devbin-steps fold:.devbin-fold'}
NEW=${NEW:-.devbin-fold}
HEADLINE=${HEADLINE:-fold:.devbin-fold}
. docs/bench/nvidia-h200/record-steps.sh "$@"
