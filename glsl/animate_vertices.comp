#version 450 core
// Vertex animation: one invocation per deformed vertex poses it for this frame into the scene's
// vertex buffer (and tangents), which every method, the clustering and the visibility buffer's
// rebuilt attributes read. Morph targets are added in the mesh's space, then the skin (the
// weighted joint matrices) or the mesh's node matrix places it in the world; the normal goes by
// the cofactors (the inverse transpose times the determinant, whose sign is put back), the
// tangent by the matrix, its w turned where the matrix mirrors. Mirrored on the CPU by
// ml::deformVertex (scenes/animation_pose.h), operation for operation.
#include "include/bindings.h"

layout(local_size_x = ML_DEFORM_WORKGROUP) in;

struct DeformVertex {
    vec4 position;    // rest, in the mesh's space
    vec4 normal;
    vec4 tangent;     // w: the bitangent's sign
    uvec4 info;       // x: scene vertex, y: deformed mesh, z: index within the mesh
    uvec4 joints[2];  // into the skin's joints
    vec4 weights[2];
};
struct DeformMesh {
    uvec4 pose;   // x: its matrix (vec4 index into the pose), y: its skin's first joint matrix or ML_DEFORM_NO_SKIN,
                  // z: its first morph weight (float index), w: morph targets
    uvec4 morph;  // x: its first morph delta, y: its vertex count
};

layout(std430, binding = ML_SSBO_DEFORM_VERTICES) readonly buffer DeformVertices { DeformVertex deformVertices[]; };
layout(std430, binding = ML_SSBO_DEFORM_MESHES) readonly buffer DeformMeshes { DeformMesh deformMeshes[]; };
layout(std430, binding = ML_SSBO_MORPH_DELTAS) readonly buffer MorphDeltas { vec4 morphDeltas[]; };  // 3 per delta
layout(std430, binding = ML_SSBO_ANIMATION_POSE) readonly buffer AnimationPose { vec4 pose[]; };
layout(std430, binding = ML_SSBO_VERTICES) writeonly buffer Vertices { float vertexData[]; };  // 8 floats a vertex
#if ML_DEFORM_TANGENTS
layout(std430, binding = ML_SSBO_VERTEX_TANGENTS) writeonly buffer Tangents { vec4 tangents[]; };
#endif

uniform uint u_vertexCount;

mat4 poseMatrix(uint first) { return mat4(pose[first], pose[first + 1u], pose[first + 2u], pose[first + 3u]); }
float poseFloat(uint index) { return pose[index / 4u][index % 4u]; }

vec3 safeNormalize(vec3 v) {
    float len = length(v);
    return len > 0.0 && !isinf(len) && !isnan(len) ? v / len : vec3(0.0, 1.0, 0.0);
}

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_vertexCount) return;
    DeformVertex v = deformVertices[i];
    DeformMesh mesh = deformMeshes[v.info.y];

    vec3 position = v.position.xyz;
    vec3 normal = v.normal.xyz;
    vec4 tangent = v.tangent;
    for (uint t = 0u; t < mesh.pose.w; ++t) {
        float w = poseFloat(mesh.pose.z + t);
        if (w == 0.0) continue;
        uint d = 3u * (mesh.morph.x + t * mesh.morph.y + v.info.z);
        position += w * morphDeltas[d].xyz;
        normal += w * morphDeltas[d + 1u].xyz;
        tangent += vec4(w * morphDeltas[d + 2u].xyz, 0.0);
    }

    mat4 matrix = poseMatrix(mesh.pose.x);
    if (mesh.pose.y != ML_DEFORM_NO_SKIN) {
        mat4 skinned = mat4(0.0);
        bool any = false;
        for (int set = 0; set < 2; ++set)
            for (int c = 0; c < 4; ++c) {
                float w = v.weights[set][c];
                if (w == 0.0) continue;
                skinned += poseMatrix(mesh.pose.y + 4u * v.joints[set][c]) * w;
                any = true;
            }
        if (any) matrix = skinned;
    }

    mat3 linear = mat3(matrix);
    mat3 normalMatrix = mat3(cross(linear[1], linear[2]), cross(linear[2], linear[0]), cross(linear[0], linear[1]));
    float det = dot(linear[0], cross(linear[1], linear[2]));
    if (det < 0.0) normalMatrix = -normalMatrix;
    vec3 worldPosition = (matrix * vec4(position, 1.0)).xyz;
    vec3 worldNormal = safeNormalize(normalMatrix * normal);

    uint s = v.info.x;
    vertexData[8u * s] = worldPosition.x;
    vertexData[8u * s + 1u] = worldPosition.y;
    vertexData[8u * s + 2u] = worldPosition.z;
    vertexData[8u * s + 3u] = worldNormal.x;
    vertexData[8u * s + 4u] = worldNormal.y;
    vertexData[8u * s + 5u] = worldNormal.z;
#if ML_DEFORM_TANGENTS
    vec3 direction = linear * tangent.xyz;
    float len = length(direction);
    bool usable = len > 0.0 && !isinf(len) && !isnan(len);
    tangents[s] = vec4(usable ? direction / len : vec3(1.0, 0.0, 0.0),
                       (tangent.w < 0.0 ? -1.0 : 1.0) * (det < 0.0 ? -1.0 : 1.0));
#endif
}
