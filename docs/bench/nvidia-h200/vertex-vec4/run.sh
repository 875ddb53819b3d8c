#!/usr/bin/env bash
# Issue 30: the scene's vertices read as two vec4s a vertex (glsl/include/scene_geometry.glsl),
# against main, on an H200 (nvidia-h200). Builds and the gas station (.corpus-glass/) in
# .devbin-vv.txz, carried with .gl alone:
#   .devbin-main/   before: main at 659ac00
#   .devbin-vec4/   the vertices as vec4s
# One call (steps: ../record-steps.sh): round 1 (its first points warm the clock), frames, round 2,
# round 3.
S=docs/bench/nvidia-h200/vertex-vec4
BUILDS=${BUILDS:-'main:.devbin-main vec4:.devbin-vec4'}
NEW=${NEW:-.devbin-vec4}
HEADLINE=${HEADLINE:-vec4:.devbin-vec4}
. docs/bench/nvidia-h200/record-steps.sh "$@"
