#!/usr/bin/env bash
# Issue 30: the exact G-buffer's third target (emissive, occlusion) written and read only at the
# pixels that have them, and the list rounds' normal bound (lights behind every served point's
# surface dropped). Against main, on an H200 (nvidia-h200). Builds, in one archive .devbin-gn.txz
# with .devbin-lib, carried with .gl, .corpus-glass (corpus/amd/gas_station) and Sponza's four
# parts (.sponza-part0..3, unpacked into /root/.corpus-sponza; the call ran with docs/bench moved
# out of the tree but for the files it reads, so that the tree and Sponza fit the device tool's
# 64 MiB together):
#   .devbin-main/    before: main at 333036c
#   .devbin-g32/     the G-buffer alone: 6cd4661
#   .devbin-ncull/   the G-buffer and the normal bound: 789d0b1
# First call (call1/): warm, round 1, sponza 1, frames, targets-4m, round 2, sponza 2. Second
# (call2/), with BUILDS='main:.devbin-main ncull:.devbin-ncull': round 3, sponza 3, headline,
# round 4, sponza 4 (its warm-up by hand, with the bench's default radius: call2/warm.log).
# Sponza's parts are unpacked by ../record-steps.sh's sponza step (this script did so itself then).
S=docs/bench/nvidia-h200/gbuffer-normals
BUILDS=${BUILDS:-'main:.devbin-main g32:.devbin-g32 ncull:.devbin-ncull'}
NEW=${NEW:-.devbin-ncull}
HEADLINE=${HEADLINE:-ncull:.devbin-ncull}
. docs/bench/nvidia-h200/record-steps.sh "$@"
