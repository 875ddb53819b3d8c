// Light lists served to a workgroup's pixels one list at a time, for the compute passes that
// light many points of one screen tile (deferred_lighting.comp, glass_shade.comp). Each round
// serves the smallest list key any invocation waits for: the box of the served points is taken,
// the list staged in shared memory a batch of lights at a time (one light per invocation, read
// once per workgroup instead of once per point) and only the lights whose sphere reaches that box
// kept: a cluster is a whole screen tile deep in its slice, an 8x8 block of surface points far
// smaller, so most of a long list falls away (Andersson 2011's tiled culling inside the
// cluster's list). A light is dropped only where it adds exactly zero to every point (beyond its
// radius, or behind every served point's surface, with a margin for rounding), and the rest are
// shaded in list order, so the sums are bit for bit those of the per-point loop
// (shadeClusterLights). Needs cluster_lists (per-cluster lists, not ML_ZBIN), lights, shading and
// spot_cone; every invocation of the workgroup must call serveListRound alike (it holds barriers).
const uint kLightBatch = uint(ML_SCREEN_TILE * ML_SCREEN_TILE);  // one light per invocation
const uint kMaskWords = (kLightBatch + 31u) / 32u;
const uint kNoList = 0xFFFFFFFFu;

shared uint s_listKey;
shared uint s_boundsMin[3], s_boundsMax[3];  // the box of the served pixels, as orderedBits
#ifndef ML_LIST_ROUNDS_NORMAL_BOUND
#define ML_LIST_ROUNDS_NORMAL_BOUND 1  // drop the lights behind every served point's surface
#endif
shared uint s_normalMin[3], s_normalMax[3];  // the box of their normals, likewise
shared Light s_lights[kLightBatch];
#if ML_SHADOW_RAYS && defined(ML_SHADOW_SAMPLED_LIGHTING)
shared uint s_lightIndices[kLightBatch];  // --shadows sampled: each staged light's index, its draws' key
#endif
#if ML_SPOT_LIGHTS
shared vec4 s_cones[kLightBatch];
#endif
shared uint s_reaches[2][kMaskWords];  // staged lights that reach the box; two, by batch parity

// A float's bits as a uint that orders as the float does, for min/max with integer atomics.
uint orderedBits(float f) {
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : u | 0x80000000u;
}
float orderedFloat(uint u) { return uintBitsToFloat((u & 0x80000000u) != 0u ? u & 0x7FFFFFFFu : ~u); }

// The served points as the tests below read them, worked out once a round.
struct ServedBounds {
    vec3 lo, hi;         // the box of their positions
    vec3 centre;
    float halfDiagonal;  // the box's, grown for rounding: its bounding sphere for the spot test
    vec3 axis;           // every normal lies within spread of axis
    float spread;
    float slack;         // |axis|.halfExtent: the most axis.(centre - p) reaches over the box
};

// Could the light add anything to a point in the box whose normal is within spread of axis?
// Not where it is beyond its reach of the box, nor where it lies behind every such point's
// surface: for a point p within its reach R and normal n, n.(L - p) is at most
// axis.(L - centre) + |axis|.halfExtent + spread R, and where that is below zero the shading's
// N.L is not above it (shadeIncoming adds nothing). Conservative: the margins cover the rounding
// of the shader's own distance and N.L, and a NaN light or normal is kept (the loop then does
// what the per-pixel loop does with it). A spot must also reach the box's bounding sphere with
// its cone.
bool lightReachesBox(vec4 positionRadius, vec4 cone, ServedBounds b) {
    vec3 d = positionRadius.xyz - clamp(positionRadius.xyz, b.lo, b.hi);
    float reach = positionRadius.w * 1.001 + 1e-3;
    if (dot(d, d) > reach * reach) return false;
#if ML_LIST_ROUNDS_NORMAL_BOUND
    float front = dot(b.axis, positionRadius.xyz - b.centre) + b.slack + b.spread * reach;
    if (front < -(1e-3 * reach + 1e-4)) return false;
#endif
    return spotMayReachSphere(positionRadius.xyz, cone.xyz, cone.w, reach, b.centre, b.halfDiagonal);
}

// One round. `pending`: the list key this invocation waits for (kNoList: none); `s`, `viewDir`:
// its point. Returns false, serving nothing, when no invocation waits; else `served` says whether
// this one was, and its lightSum has grown by the list's lights.
bool serveListRound(uint pending, SurfacePoint s, vec3 viewDir, inout LightSum lightSum, out bool served) {
    uint lane = gl_LocalInvocationIndex;
    barrier();
    if (lane == 0u) {
        s_listKey = kNoList;
        for (int a = 0; a < 3; ++a) {
            s_boundsMin[a] = s_normalMin[a] = 0xFFFFFFFFu;
            s_boundsMax[a] = s_normalMax[a] = 0u;
        }
    }
    if (lane < kMaskWords) s_reaches[0][lane] = 0u;
    barrier();
    if (pending != kNoList) atomicMin(s_listKey, pending);
    barrier();
    uint listKey = s_listKey;
    served = false;
    if (listKey == kNoList) return false;
    served = pending == listKey;
    if (served) {
        for (int a = 0; a < 3; ++a) {
            atomicMin(s_boundsMin[a], orderedBits(s.position[a]));
            atomicMax(s_boundsMax[a], orderedBits(s.position[a]));
#if ML_LIST_ROUNDS_NORMAL_BOUND
            atomicMin(s_normalMin[a], orderedBits(s.normal[a]));
            atomicMax(s_normalMax[a], orderedBits(s.normal[a]));
#endif
        }
    }
    barrier();
    ServedBounds b;
    b.lo = vec3(orderedFloat(s_boundsMin[0]), orderedFloat(s_boundsMin[1]), orderedFloat(s_boundsMin[2]));
    b.hi = vec3(orderedFloat(s_boundsMax[0]), orderedFloat(s_boundsMax[1]), orderedFloat(s_boundsMax[2]));
    b.centre = 0.5 * (b.lo + b.hi);
    b.halfDiagonal = 0.5 * length(b.hi - b.lo) + 1e-3;
#if ML_LIST_ROUNDS_NORMAL_BOUND
    vec3 normalLo = vec3(orderedFloat(s_normalMin[0]), orderedFloat(s_normalMin[1]), orderedFloat(s_normalMin[2]));
    vec3 normalHi = vec3(orderedFloat(s_normalMax[0]), orderedFloat(s_normalMax[1]), orderedFloat(s_normalMax[2]));
    // Every normal lies in the box, so within half its diagonal of its centre (rounded up).
    b.axis = 0.5 * (normalLo + normalHi);
    b.spread = 0.5 * length(normalHi - normalLo) * 1.001 + 1e-5;
    b.slack = dot(abs(b.axis), 0.5 * (b.hi - b.lo));
#endif
    uvec2 range = clusterListRange(listKey);
    uint parity = 0u;
    for (uint base = 0u; base < range.y; base += kLightBatch) {
        // The other parity's mask was last read before the previous batch's closing barrier.
        if (lane < kMaskWords) s_reaches[parity ^ 1u][lane] = 0u;
        if (base + lane < range.y) {
            uint index = lightIndices[range.x + base + lane];
            Light l = lights[index];
            vec4 cone = lightCone(index);
            s_lights[lane] = l;
#if ML_SHADOW_RAYS && defined(ML_SHADOW_SAMPLED_LIGHTING)
            s_lightIndices[lane] = index;
#endif
#if ML_SPOT_LIGHTS
            s_cones[lane] = cone;
#endif
            if (lightReachesBox(l.positionRadius, cone, b)) atomicOr(s_reaches[parity][lane / 32u], 1u << (lane % 32u));
        }
        barrier();
        if (served) {
            for (uint w = 0u; w < kMaskWords; ++w) {
                uint bits = s_reaches[parity][w];
                while (bits != 0u) {
                    uint i = w * 32u + uint(findLSB(bits));
                    bits &= bits - 1u;
#if ML_SPOT_LIGHTS
                    vec4 cone = s_cones[i];
#else
                    vec4 cone = lightCone(0u);  // a point's: the set has no spots
#endif
                    vec3 c = shadeLight(s, viewDir, s_lights[i].positionRadius, s_lights[i].colorCosInner, cone);
                    addLight(lightSum, c);
                    ML_OFFER_SHADOW_SAMPLE(c, vec4(s_lights[i].positionRadius.xyz, 1.0), s_lightIndices[i]);
                }
            }
        }
        barrier();
        parity ^= 1u;
    }
    return true;
}
