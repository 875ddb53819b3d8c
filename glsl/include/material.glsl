// Materials, mirrored in C++ by ml::GpuMaterial (renderer/gpu_types.h).
struct Material {
    vec4 baseColorFactor;  // linear
    vec4 params;           // x: specular strength, y: shininess, z: has texture (0/1)
};
layout(std430, binding = ML_SSBO_MATERIALS) readonly buffer MaterialBuffer { Material materials[]; };
layout(binding = ML_TEX_BASE_COLOR) uniform sampler2D u_baseColorTexture;  // sRGB texture: sampled as linear

SurfacePoint surfaceFromMaterial(uint materialIndex, vec3 worldPos, vec3 worldNormal, vec2 uv) {
    Material m = materials[materialIndex];
    SurfacePoint s;
    s.position = worldPos;
    s.normal = normalize(worldNormal);
    vec4 base = m.baseColorFactor;
    if (m.params.z > 0.5) base *= texture(u_baseColorTexture, uv);
    s.albedo = base.rgb;
    s.specularStrength = m.params.x;
    s.shininess = m.params.y;
    return s;
}
