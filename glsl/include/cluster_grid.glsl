// The cluster grid on the GPU, mirrored in C++ by ml::ClusterGridGpu (renderer/gpu_types.h);
// the maths mirrors renderer/clustering/cluster_grid.{h,cpp}.
struct ClusterGridData {
    uvec4 dims;       // tilesX, tilesY, slices, cluster count
    vec4 slicing;     // zNear, zFar of the range sliced; scale, bias: slice = floor(f(z) * scale + bias)
    vec4 tile;        // tile size in pixels, logarithmic (0/1), camera near, camera far
    uvec4 reduction;  // fitted slicing: min and max visible view depth as float bits
    uvec4 options;    // x: fitted (0/1), y: per-cluster cap (0: exact lists), z: active-only (0/1), w: debug view
};

#ifdef ML_CLUSTER_GRID_WRITABLE
layout(std430, binding = ML_SSBO_CLUSTER_GRID) coherent buffer ClusterGridBuffer { ClusterGridData grid; };
#else
layout(std430, binding = ML_SSBO_CLUSTER_GRID) readonly buffer ClusterGridBuffer { ClusterGridData grid; };
#endif

uint clusterSliceCount() { return grid.dims.z; }

uint sliceForDepth(float z) {
    float f = grid.tile.y > 0.5 ? log(max(z, 1e-7)) : z;
    float s = floor(f * grid.slicing.z + grid.slicing.w);
    return uint(clamp(s, 0.0, float(grid.dims.z - 1u)));
}

uvec2 tileForPixel(vec2 fragCoord) {
    uvec2 t = uvec2(max(fragCoord / grid.tile.x, vec2(0.0)));
    return min(t, grid.dims.xy - 1u);
}

uint clusterIndex(uvec3 c) { return c.x + grid.dims.x * (c.y + grid.dims.y * c.z); }

uint clusterForFragment(vec2 fragCoord, float viewDepth) {
    return clusterIndex(uvec3(tileForPixel(fragCoord), sliceForDepth(viewDepth)));
}

// Depth of the boundary below slice k of the depth range `sliced` (grid.slicing.xy).
float sliceBoundary(uint k, vec2 sliced) {
    float t = float(k) / float(grid.dims.z);
    float n = sliced.x, f = sliced.y;
    return grid.tile.y > 0.5 ? n * pow(f / n, t) : n + (f - n) * t;
}

// The view depths a cluster's volume spans: the first and last slice reach the camera's near
// and far planes, and both ends are widened by a relative epsilon so a fragment's slice lookup
// can never land outside the volume its lights were tested against (mirrors ml::clusterFrustum).
// `sliced`: the depth range sliced, grid.slicing.xy (cluster_bounds.comp passes the range it
// slices itself before the grid holds it).
vec2 clusterDepthExtent(uint slice, vec2 sliced) {
    float z0 = slice == 0u ? min(grid.tile.z, sliced.x) : sliceBoundary(slice, sliced);
    float z1 = slice + 1u == grid.dims.z ? max(grid.tile.w, sliced.y) : sliceBoundary(slice + 1u, sliced);
    return vec2(z0 * (1.0 - 1e-4), z1 * (1.0 + 1e-4));
}
vec2 clusterDepthExtent(uint slice) { return clusterDepthExtent(slice, grid.slicing.xy); }

// The tile's rectangle in NDC: xy the lower-left corner, zw the upper-right (clamped to the
// screen; needs frame_uniforms).
vec4 clusterTileNdc(uvec2 tile) {
    vec2 p0 = min(vec2(tile) * grid.tile.x, u_viewport.xy);
    vec2 p1 = min(vec2(tile + 1u) * grid.tile.x, u_viewport.xy);
    return vec4(p0, p1) / u_viewport.xyxy * 2.0 - 1.0;
}
