// Clustered deferred lighting of one pixel from the G-buffer, shared by the full-screen
// fragment resolve and the compute resolve. Position is rebuilt from depth; the rest is
// decoded from the --gbuffer layout (gbuffer_layout.glsl, read by gbuffer_fetch.glsl).
vec4 resolvePixel(ivec2 p) {
    float depth = texelFetch(u_depth, p, 0).r;
    if (depth >= 1.0) return vec4(0.0, 0.0, 0.0, 1.0);  // background, as the forward methods clear it
    vec2 ndc = (vec2(p) + 0.5) * u_viewport.zw * 2.0 - 1.0;
    vec4 viewPos = u_invProj * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    viewPos /= viewPos.w;
    SurfacePoint s;
    s.position = u_cameraPos.xyz + mat3(u_invView) * viewPos.xyz;
    decodeGBuffer(fetchGBuffer(p), s);
    vec3 viewDir = normalize(u_cameraPos.xyz - s.position);
    float viewDepth = -viewPos.z;
    uint cluster = clusterForFragment(vec2(p) + 0.5, viewDepth);
    uint view = grid.options.w;
    vec3 color = vec3(0.0);
    if (view == ML_VIEW_SHADED || view == ML_VIEW_OVERFLOW) color = shadeAmbient(s) + shadeClusterLights(s, viewDir, cluster, viewDepth);
    return vec4(debugViewColor(view, s, cluster, viewDepth, color), 1.0);
}
