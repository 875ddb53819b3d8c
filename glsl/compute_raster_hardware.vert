#version 450 core
// The compute raster's hardware lists (renderer/passes/compute_raster.h): the triangles it leaves
// to the hardware (where the GPU clips at the viewport, those that cross a side, the eye plane or
// the guard band; the alpha-tested ones across the eye plane or past the guard band; any past
// the lists' capacity), drawn as non-indexed lists that pull each triangle's vertices: the opaque
// list from entry 0, each alpha-tested span's from u_listFirst. Outputs what scene.vert gives
// visibility.frag, the triangle recovered as v_firstTriangle + gl_PrimitiveID.
#include "include/bindings.h"
#include "include/frame_uniforms.glsl"

layout(std430, binding = ML_SSBO_VERTICES) readonly buffer Vertices { float vertexData[]; };  // 8 floats a vertex
layout(std430, binding = ML_SSBO_INDICES) readonly buffer Indices { uint indexData[]; };
layout(std430, binding = ML_SSBO_TRIANGLE_MATERIALS) readonly buffer TriangleMaterials { uint triangleMaterial[]; };
layout(std430, binding = ML_SSBO_RASTER_HARDWARE) readonly buffer RasterHardware { uint hardwareTriangles[]; };

uniform uint u_listFirst;  // the draw's first entry (its `first` / 3): gl_PrimitiveID counts from it

layout(location = 0) out vec3 v_worldPos;
layout(location = 3) flat out uint v_materialIndex;
layout(location = 4) flat out uint v_firstTriangle;

invariant gl_Position;

void main() {
    uint primitive = uint(gl_VertexID) / 3u;
    uint triangle = hardwareTriangles[primitive];
    uint v = indexData[3u * triangle + uint(gl_VertexID) % 3u];
    vec3 position = vec3(vertexData[8u * v], vertexData[8u * v + 1u], vertexData[8u * v + 2u]);
    v_worldPos = position;
    v_materialIndex = triangleMaterial[triangle];
    v_firstTriangle = triangle - (primitive - u_listFirst);
    gl_Position = u_proj * vec4(mat3(u_view) * (position - u_cameraPos.xyz), 1.0);
}
