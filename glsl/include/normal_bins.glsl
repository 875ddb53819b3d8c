// --normal-cones (Olsson et al. 2012, "Clustered deferred and forward shading", normal cones):
// view-space normal directions quantised on a cube. Each face (+x, -x, +y, -y, +z, -z) is cut
// into ML_NORMAL_BIN_CELLS^2 cells, a bin each. A bin is only a key: what the assignment tests
// is each (cluster, bin) list's own cone, around the normals its samples actually have.

// Bin of a unit view-space normal.
uint normalBin(vec3 n) {
    vec3 a = abs(n);
    uint axis = (a.x >= a.y && a.x >= a.z) ? 0u : (a.y >= a.z ? 1u : 2u);
    float major = n[axis];
    vec2 uv = vec2(n[(axis + 1u) % 3u], n[(axis + 2u) % 3u]) / max(abs(major), 1e-20);
    float cells = float(ML_NORMAL_BIN_CELLS);
    uvec2 cell = uvec2(clamp(floor((uv * 0.5 + 0.5) * cells), vec2(0.0), vec2(cells - 1.0)));
    uint face = axis * 2u + (major < 0.0 ? 1u : 0u);
    return (face * uint(ML_NORMAL_BIN_CELLS) + cell.y) * uint(ML_NORMAL_BIN_CELLS) + cell.x;
}

// The axis of a list's normal cone from its fixed-point normal sum (the +z axis when the
// normals cancel out; the half-angle then covers them all).
vec3 normalConeAxis(ivec3 sum) {
    vec3 v = vec3(sum);
    return dot(v, v) > 0.0 ? normalize(v) : vec3(0.0, 0.0, 1.0);
}

// A list's cone from its stored sum and 1 - min cos: xyz the axis, w the half-angle, widened by
// a milliradian for the rounding between this pass and the resolve.
vec4 normalConeOfList(ivec4 stored) {
    float cosHalf = 1.0 - intBitsToFloat(stored.w);
    return vec4(normalConeAxis(stored.xyz), acos(clamp(cosHalf, -1.0, 1.0)) + 1e-3);
}

// Can a light (view-space centre c) reach, with N.L > 0, a surface at some point p of the box
// whose normal lies in the cone? For w = c - p, some normal of the cone has N.w > 0 iff
// angle(axis, w) < 90 degrees + half-angle, i.e. axis.w + sin(half) |w| > 0. That is a convex
// function of p, so its maximum over the box is at one of the 8 corners: the test is exact for
// the box and conservative for the cluster inside it. A light it rejects contributes exactly
// zero there (the shading model's max(N.L, 0) weighs both terms).
bool lightMayFaceNormalCone(vec4 cone, vec3 boxMin, vec3 boxMax, vec3 c) {
    if (cone.w >= 1.5707) return true;
    float s = sin(cone.w);
    for (int k = 0; k < 8; ++k) {
        vec3 p = vec3((k & 1) != 0 ? boxMax.x : boxMin.x, (k & 2) != 0 ? boxMax.y : boxMin.y, (k & 4) != 0 ? boxMax.z : boxMin.z);
        vec3 w = c - p;
        if (dot(cone.xyz, w) + s * length(w) > 0.0) return true;
    }
    return false;
}
