// The G-buffer's targets as GBuffer::bindForReading() binds them (ML_TEX_GBUFFER0..), and the
// depth, for every pass that reads the G-buffer back: the deferred lighting and --normal-cones'
// normal bins. Both decode with decodeGBuffer (gbuffer_layout.glsl), so they see the same normal
// in every --gbuffer layout. Needs gbuffer_layout.glsl.
layout(binding = ML_TEX_DEPTH) uniform sampler2D u_depth;
#if ML_GBUFFER_FLOAT_TARGETS == 0
layout(binding = ML_TEX_GBUFFER0) uniform usampler2D u_gPacked;
#else
layout(binding = ML_TEX_GBUFFER0) uniform sampler2D u_gTarget0;
layout(binding = ML_TEX_GBUFFER1) uniform sampler2D u_gTarget1;
#if ML_GBUFFER_FLOAT_TARGETS >= 3
layout(binding = ML_TEX_GBUFFER2) uniform sampler2D u_gTarget2;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 4
layout(binding = ML_TEX_GBUFFER3) uniform sampler2D u_gTarget3;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 5
layout(binding = ML_TEX_GBUFFER4) uniform sampler2D u_gTarget4;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 6
layout(binding = ML_TEX_GBUFFER5) uniform sampler2D u_gTarget5;
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 7
layout(binding = ML_TEX_GBUFFER6) uniform sampler2D u_gTarget6;
#endif
#if ML_GBUFFER_FLOAT_TARGETS == 8
layout(binding = ML_TEX_GBUFFER7) uniform sampler2D u_gTarget7;
#endif
#endif

GBufferTexel fetchGBuffer(ivec2 p) {
    GBufferTexel t;
    t.target[0] = t.target[1] = t.target[2] = t.target[3] = t.target[4] = t.target[5] = t.target[6] = t.target[7] = vec4(0.0);
    t.bits = uvec4(0u);
#if ML_GBUFFER_FLOAT_TARGETS == 0
    t.bits = texelFetch(u_gPacked, p, 0);
#else
    t.target[0] = texelFetch(u_gTarget0, p, 0);
    t.target[1] = texelFetch(u_gTarget1, p, 0);
#if ML_GBUFFER_FLOAT_TARGETS >= 3
    if (gbufferUsesTarget2(t)) t.target[2] = texelFetch(u_gTarget2, p, 0);
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 4
    if (gbufferUsesTarget3(t)) t.target[3] = texelFetch(u_gTarget3, p, 0);
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 5
    if (gbufferUsesTarget4(t)) t.target[4] = texelFetch(u_gTarget4, p, 0);
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 6
    if (gbufferUsesTarget5(t)) t.target[5] = texelFetch(u_gTarget5, p, 0);
#endif
#if ML_GBUFFER_FLOAT_TARGETS >= 7
    if (gbufferUsesTarget6(t)) t.target[6] = texelFetch(u_gTarget6, p, 0);
#endif
#if ML_GBUFFER_FLOAT_TARGETS == 8
    if (gbufferUsesTarget7(t)) t.target[7] = texelFetch(u_gTarget7, p, 0);
#endif
#endif
    return t;
}
