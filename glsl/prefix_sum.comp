#version 450 core
// Exclusive prefix sum of uints, in place, in blocks of 2 x ML_SCAN_WORKGROUP elements
// (Blelloch's up-sweep / down-sweep in shared memory). Phase 0 scans each block and writes its
// total to blockSums; the host scans blockSums the same way (recursively) and phase 1 adds each
// block's offset back. Elements at or past u_count are read as 0 and never written.
#include "include/bindings.h"

layout(local_size_x = ML_SCAN_WORKGROUP) in;
layout(std430, binding = ML_SSBO_SCAN_DATA) buffer ScanData { uint data[]; };
layout(std430, binding = ML_SSBO_SCAN_BLOCKS) buffer ScanBlocks { uint blockSums[]; };

uniform uint u_count;
uniform uint u_phase;  // 0: scan blocks, 1: add block offsets

const uint kBlock = 2u * ML_SCAN_WORKGROUP;
shared uint s_values[kBlock];

void main() {
    uint t = gl_LocalInvocationID.x;
    uint block = gl_WorkGroupID.x;
    uint i0 = block * kBlock + t;
    uint i1 = i0 + ML_SCAN_WORKGROUP;

    if (u_phase == 1u) {
        uint offset = blockSums[block];
        if (i0 < u_count) data[i0] += offset;
        if (i1 < u_count) data[i1] += offset;
        return;
    }

    s_values[t] = i0 < u_count ? data[i0] : 0u;
    s_values[t + ML_SCAN_WORKGROUP] = i1 < u_count ? data[i1] : 0u;

    // Up-sweep: build partial sums in place.
    uint stride = 1u;
    for (uint width = kBlock >> 1; width > 0u; width >>= 1) {
        barrier();
        if (t < width) {
            uint a = stride * (2u * t + 1u) - 1u;
            uint b = stride * (2u * t + 2u) - 1u;
            s_values[b] += s_values[a];
        }
        stride <<= 1;
    }
    barrier();
    if (t == 0u) {
        blockSums[block] = s_values[kBlock - 1u];
        s_values[kBlock - 1u] = 0u;
    }
    // Down-sweep: turn the partial sums into an exclusive scan.
    for (uint width = 1u; width < kBlock; width <<= 1) {
        stride >>= 1;
        barrier();
        if (t < width) {
            uint a = stride * (2u * t + 1u) - 1u;
            uint b = stride * (2u * t + 2u) - 1u;
            uint left = s_values[a];
            s_values[a] = s_values[b];
            s_values[b] += left;
        }
    }
    barrier();
    if (i0 < u_count) data[i0] = s_values[t];
    if (i1 < u_count) data[i1] = s_values[t + ML_SCAN_WORKGROUP];
}
