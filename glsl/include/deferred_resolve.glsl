// Clustered deferred lighting of one pixel from the G-buffer, shared by the full-screen
// fragment resolve and the compute resolve. Position is rebuilt from depth; the rest is
// decoded from the --gbuffer layout (gbuffer_layout.glsl, read by gbuffer_fetch.glsl).
#include "include/window_depth.glsl"

// What the light loop needs to know of a pixel.
struct ResolvedPixel {
    SurfacePoint surface;
    vec3 viewDir;
    float viewDepth;
    uint cluster;
};

// False for background pixels (nothing was drawn there).
bool resolveSurface(ivec2 p, out ResolvedPixel px) {
    float depth = texelFetch(u_depth, p, 0).r;
    if (isBackgroundDepth(depth)) return false;
    vec3 viewPos = viewPositionAtWindow(vec2(p) + 0.5, depth);
    GBufferTexel texel = fetchGBuffer(p);
#if ML_GBUFFER_STORES_POSITION
    // Shaded at the stored point; the cluster still comes from depth, as the grid was built.
    px.surface.position = gbufferPosition(texel, vec2(p) + 0.5);
#else
    px.surface.position = u_cameraPos.xyz + mat3(u_invView) * viewPos;
#endif
    decodeGBuffer(texel, px.surface);
    px.viewDir = normalize(u_cameraPos.xyz - px.surface.position);
    px.viewDepth = -viewPos.z;
    px.cluster = clusterForFragment(vec2(p) + 0.5, px.viewDepth);
    return true;
}

// The views that show the lit colour (the others show the surface or the grid).
bool viewShadesLights() {
    uint view = grid.options.w;
    return view == ML_VIEW_SHADED || view == ML_VIEW_OVERFLOW;
}

// The pixel's output from the sum of its cluster lights (zero when the view shades none).
vec4 finishPixel(ResolvedPixel px, vec3 lightSum) {
    vec3 color = viewShadesLights() ? shadeUnclustered(px.surface, px.viewDir) + lightSum : vec3(0.0);
    return vec4(debugViewColor(grid.options.w, px.surface, px.cluster, px.viewDepth, color), 1.0);
}

const vec4 kBackground = vec4(0.0, 0.0, 0.0, 1.0);  // as the forward methods clear it

// One pixel on its own, reading its cluster's lights straight from the buffers.
vec4 resolvePixel(ivec2 p) {
    ResolvedPixel px;
    if (!resolveSurface(p, px)) return kBackground;
    vec3 lightSum = vec3(0.0);
    if (viewShadesLights()) lightSum = shadeClusterLights(px.surface, px.viewDir, px.cluster, px.viewDepth);
    return finishPixel(px, lightSum);
}
