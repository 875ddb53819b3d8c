#version 450 core
// Visibility buffer: the raster pass writes only depth and which triangle is nearest (index + 1;
// 0 is background). Everything else is rebuilt in compute (visibility_resolve.comp).
layout(location = 0) out uint o_triangle;
layout(location = 4) flat in uint v_firstTriangle;  // the draw range's first triangle (scene.vert)

void main() { o_triangle = v_firstTriangle + uint(gl_PrimitiveID) + 1u; }
