#version 450 core
// --view overdraw: fragment counts to display colours in the HDR target. 0 (background) is
// black; 1 (every pixel shaded once, the floor) blue, through green and yellow, to 8 and more red.
#include "include/bindings.h"
#include "include/heat_color.glsl"

layout(local_size_x = ML_SCREEN_TILE, local_size_y = ML_SCREEN_TILE) in;
layout(binding = ML_TEX_OVERDRAW_COUNTS) uniform sampler2D u_counts;
layout(binding = ML_IMG_HDR, rgba32f) uniform writeonly image2D u_hdr;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, textureSize(u_counts, 0)))) return;
    float fragments = texelFetch(u_counts, p, 0).r;
    vec3 color = fragments < 0.5 ? vec3(0.0) : heatColor((fragments - 1.0) / 7.0);
    imageStore(u_hdr, p, vec4(color, 1.0));
}
