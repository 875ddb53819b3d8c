// The region a spot light can light: its cone (apex at the light, unit axis, outer half-angle
// at most 90 degrees) cut by the sphere of its radius, a convex "spherical sector". The
// clustering bounds spots by it (docs/methods-and-clustering.md), mirrored on the CPU by
// renderer/clustering/spot_cone.h. Every test is conservative: the sector never misses a point
// the shading lights (include/shading.glsl: zero at and outside the outer cone). A point light
// (cosOuter = ML_POINT_LIGHT_CONE_COS) is its whole sphere in every function.

// Relative slack on the cone tests: float rounding in the shading's own cosine must never
// turn a lit point into a rejected one.
const float kSpotSlack = 1e-4;

// ML_SPOT_LIGHTS 0: the light set has no spots (the renderer sets it from the lights), so every
// spot path compiles out and a points-only scene pays nothing for them. 1 unless set.
#ifndef ML_SPOT_LIGHTS
#define ML_SPOT_LIGHTS 1
#endif

bool isSpotCone(float cosOuter) { return ML_SPOT_LIGHTS != 0 && cosOuter > -1.5; }

// The sector's farthest extent along unit direction n, from the apex: r where n lies inside the
// cone; r cos(angle past the cone) up to 90 degrees past it; 0 (the apex) beyond. The support
// function of the sector: exact.
float spotReach(vec3 n, vec3 axis, float cosOuter, float radius) {
    float cosToAxis = dot(n, axis);
    if (cosToAxis >= cosOuter) return radius;
    float sinOuter = sqrt(max(1.0 - cosOuter * cosOuter, 0.0));
    float sinToAxis = sqrt(max(1.0 - cosToAxis * cosToAxis, 0.0));
    return radius * max(cosToAxis * cosOuter + sinToAxis * sinOuter, 0.0);
}

// A sphere holding the sector: around the cap for narrow cones (half-angle up to 45 degrees,
// where apex and rim are equally far from it), else around the cap's rim disk. A point light's
// is its own sphere, unchanged.
vec4 spotBoundingSphere(vec3 apex, vec3 axis, float cosOuter, float radius) {
    if (!isSpotCone(cosOuter)) return vec4(apex, radius);
    float slack = kSpotSlack * (radius + length(apex));
    if (cosOuter >= 0.70710678) {
        float t = radius / (2.0 * cosOuter);
        return vec4(apex + axis * t, t + slack);
    }
    float c = max(cosOuter, 0.0);
    return vec4(apex + axis * (radius * c), radius * sqrt(1.0 - c * c) + slack);
}

// Can the sector reach a sphere (centre, sphereRadius)? Wronski's "Cull that cone" (2017): the
// sphere's distance to the cone's side (a lower bound of its distance to the cone, exact where
// the nearest point is on the side), and the slab between the apex and the cap.
bool spotMayReachSphere(vec3 apex, vec3 axis, float cosOuter, float radius, vec3 center, float sphereRadius) {
    if (!isSpotCone(cosOuter)) return true;
    vec3 v = center - apex;
    float lengthSq = dot(v, v);
    float along = dot(v, axis);
    float sinOuter = sqrt(max(1.0 - cosOuter * cosOuter, 0.0));
    float toSide = cosOuter * sqrt(max(lengthSq - along * along, 0.0)) - along * sinOuter;
    float reach = sphereRadius + kSpotSlack * (sqrt(lengthSq) + sphereRadius + radius);
    return !(toSide > reach || along > radius + reach || along < -reach);
}
