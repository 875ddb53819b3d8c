// The light-vs-cluster tests of --cull on the CPU, mirroring glsl/include/light_cluster_test.glsl,
// and the exact test they are measured against: the distance from a sphere's centre to the
// cluster's convex volume (its tile's frustum between its depth extent).
//
//   corner k of a cluster:  bit 0 right (else left), bit 1 top (else bottom), bit 2 far (else near)
//
//        6-------7        the volume is the convex hull of the 8 corners: a frustum piece whose
//       /|      /|        side faces pass through the eye and whose near/far faces are planes of
//      4-------5 |        constant view depth
//      | 2-----|-3
//      |/      |/
//      0-------1
#pragma once

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "renderer/clustering/cluster_grid.h"
#include "renderer/clustering/clustering_settings.h"
#include "renderer/clustering/spot_cone.h"

namespace ml {

struct ClusterFrustum {
    std::array<glm::vec3, 8> corners;  // view space
    glm::vec2 slopeLo, slopeHi;        // x / -z and y / -z at the tile's left/bottom and right/top edges
    float zNear = 0.0f, zFar = 0.0f;   // the view depths it spans (widened as on the GPU)
};

// The volume of cluster (x, y, slice), exactly as glsl/include/cluster_grid.glsl builds it
// (clusterTileNdc, clusterDepthExtent): the first and last slices reach the camera's planes,
// the depths are widened by a relative 1e-4.
ClusterFrustum clusterFrustum(const ClusterGrid& grid, const DepthSlicing& slicing, float cameraNear, float cameraFar,
                              const glm::mat4& projection, int width, int height, std::uint32_t x, std::uint32_t y,
                              std::uint32_t slice);

// The view-space AABB of the volume (what glsl/cluster_bounds.comp stores).
Aabb boundsOf(const ClusterFrustum& cluster);

// The --cull test of the GPU for a sphere (view-space centre, radius).
bool passesCullTest(CullMode mode, const ClusterFrustum& cluster, const glm::vec3& center, float radius);

// The whole test of the GPU's assignments for a light in view space (glsl/include/
// light_cluster_test.glsl): its bounding sphere (a spot's sector's) by `mode`, then a spot's
// cone against the sphere around the cluster's AABB.
bool passesLightCullTest(CullMode mode, const ClusterFrustum& cluster, const SpotCone& light);

// Exact: does the light (view space) reach some point of the cluster's volume? A point light by
// distanceToCluster, a spot by GJK between its sector and the volume's corners.
bool lightReachesCluster(const ClusterFrustum& cluster, const SpotCone& light);

// Exact Euclidean distance from p to the cluster's volume (0 inside): the sphere reaches the
// cluster iff this is below its radius.
float distanceToCluster(const ClusterFrustum& cluster, const glm::vec3& p);

}  // namespace ml
