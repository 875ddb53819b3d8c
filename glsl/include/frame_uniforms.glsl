// Per-frame values, mirrored in C++ by ml::FrameUniforms (renderer/gpu_types.h).
layout(std140, binding = ML_UBO_FRAME) uniform FrameUniformsBlock {
    mat4 u_view;
    mat4 u_proj;
    mat4 u_viewProj;
    mat4 u_invProj;
    mat4 u_invView;
    vec4 u_cameraPos;      // xyz: world-space eye
    vec4 u_viewport;       // width, height, 1/width, 1/height
    vec4 u_depthRange;     // near, far, time (s), ambient
    uvec4 u_counts;        // x: light count, y: shading switches (ML_SHADING_*), z: falloff (ML_FALLOFF_*), w: the frame's draw seed (stochasticDrawSeed: --shadows sampled's draws)
    vec4 u_lightModel;     // x: --light-cutoff E (output units; 0 when none), y: a directional shadow ray's length
    uvec4 u_shadows;       // --shadows rays: x: the first triangle's vec4 in the BVH buffer, y: nodes, z: triangles, w: the first MASK material record's vec4
};

uint lightCount() { return u_counts.x; }
float ambientStrength() { return u_depthRange.w; }
// The light model's switches: compiled in where the renderer gives them (ShadingSwitches; a
// branch on a uniform in every (point, light) pair cost the lighting 9 %), else the uniforms.
#ifdef ML_BRDF_GGX
bool specularEnabled() { return ML_SPECULAR != 0; }
bool ggxEnabled() { return ML_BRDF_GGX != 0; }
uint falloffMode() { return uint(ML_FALLOFF); }
#else
bool specularEnabled() { return (u_counts.y & ML_SHADING_SPECULAR) != 0u; }
bool ggxEnabled() { return (u_counts.y & ML_SHADING_GGX) != 0u; }
uint falloffMode() { return u_counts.z; }
#endif
float lightCutoff() { return u_lightModel.x; }
