#version 450 core
// The capture's per-pixel counts to 0 before the count raster (renderer/passes/glass_fragments.h).
// A compute pass, as the visibility ids' clear is: on an H100 glClearNamedBufferSubData's
// full-screen clear took most of the capture's count pass.
#include "include/bindings.h"

layout(local_size_x = ML_SCAN_WORKGROUP) in;
layout(std430, binding = ML_SSBO_GLASS_PIXELS) writeonly buffer GlassPixels { uvec4 glassPixels[]; };
uniform uint u_quads;  // the counts in groups of four (the buffer is padded to a multiple of 16 B)

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < u_quads) glassPixels[i] = uvec4(0u);
}
