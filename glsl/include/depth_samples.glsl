// The frame's depth as the compute passes read it (fitted slicing, active clusters, z-binning's
// statistics): every sample of a pixel. With --msaa the depth is multisampled
// (ML_MSAA_SAMPLES > 1) and a pixel's samples may lie on different surfaces; each is shaded
// (the fragment covering it writes it), so each must find its cluster in the lists.
#ifndef ML_MSAA_SAMPLES
#define ML_MSAA_SAMPLES 1
#endif

#if ML_MSAA_SAMPLES > 1
layout(binding = ML_TEX_DEPTH) uniform sampler2DMS u_depth;
ivec2 depthSize() { return textureSize(u_depth); }
float depthSample(ivec2 p, int s) { return texelFetch(u_depth, p, s).r; }
#else
layout(binding = ML_TEX_DEPTH) uniform sampler2D u_depth;
ivec2 depthSize() { return textureSize(u_depth, 0); }
float depthSample(ivec2 p, int s) { return texelFetch(u_depth, p, 0).r; }
#endif
