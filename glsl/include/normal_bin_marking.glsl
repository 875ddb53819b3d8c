// --normal-cones: records one visible sample in the (cluster, normal bin) lists, for the opaque
// samples (cluster_normal_bins.comp, over the G-buffer) and the transparent ones
// (cluster_transparent_samples.frag) alike, in the two phases of u_phase:
//   0: set the cluster's bit of the sample's bin (and of the bins the normal, nudged by 1e-4
//      along each axis, falls in: the lighting's rounding may pick those), and add the normal to
//      each such list's sum (fixed point);
//   1: with the list's axis (its normalised sum), raise the list's 1 - cos(angle to the axis).
// Needs normal_bins.glsl.
layout(std430, binding = ML_SSBO_NORMAL_BIN_MASKS) buffer NormalBinMasks { uint normalBinMasks[]; };
layout(std430, binding = ML_SSBO_NORMAL_CONES) buffer NormalCones { ivec4 normalCones[]; };  // xyz: normal sum, w: 1 - min cos (float bits)
uniform uint u_phase;

void addToNormalList(uint key, vec3 n) {
    if (u_phase == 0u) {
        ivec3 q = ivec3(round(n * ML_NORMAL_SUM_SCALE));
        atomicAdd(normalCones[key].x, q.x);
        atomicAdd(normalCones[key].y, q.y);
        atomicAdd(normalCones[key].z, q.z);
    } else {
        vec3 axis = normalConeAxis(normalCones[key].xyz);
        atomicMax(normalCones[key].w, floatBitsToInt(max(1.0 - dot(n, axis), 0.0)));
    }
}

// n: the sample's unit view-space normal; c0, c1: its clusters at its view depth nudged by a
// relative 1e-5 down and up (equal unless the depth lies at a slice boundary).
void markNormalSample(vec3 n, uint c0, uint c1) {
    uint mask = 1u << normalBin(n);
    for (int axis = 0; axis < 3; ++axis) {
        vec3 nudge = vec3(0.0);
        nudge[axis] = 1e-4;
        mask |= (1u << normalBin(normalize(n + nudge))) | (1u << normalBin(normalize(n - nudge)));
    }
    if (u_phase == 0u) {
        atomicOr(normalBinMasks[c0], mask);
        if (c1 != c0) atomicOr(normalBinMasks[c1], mask);
    }
    for (uint bits = mask; bits != 0u; bits &= bits - 1u) {
        uint b = uint(findLSB(bits));
        addToNormalList(c0 * uint(ML_NORMAL_BINS) + b, n);
        if (c1 != c0) addToNormalList(c1 * uint(ML_NORMAL_BINS) + b, n);
    }
}
