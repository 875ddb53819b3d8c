// MeshBuilder: accumulates triangles per material for procedural scenes, then writes them into a
// Scene grouped by material, so a scene built in any order ends up with one draw range per
// material used.
//
// Conventions: y up, metres, counter-clockwise front faces, unit outward normals. Texture
// coordinates are passed in metres; each material scales them by its own repeats-per-metre, so a
// texture tiles at the same world size wherever it is used.
//
// Every primitive here winds each quad (or triangle) so that its geometric normal agrees with the
// normals it is given, and drops triangles of (near) zero area, so the callers only have to get
// the normals right.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace ml {

// A point of a parametric surface: position, normal (need not be unit length) and UV in metres.
struct SurfacePoint {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
};

// A point of a lathe profile in the (radius, height) half-plane, with its outward normal there.
struct ProfilePoint {
    float r = 0.0f;
    float y = 0.0f;
    glm::vec2 normal{1.0f, 0.0f};  // (radial, up)
};

// A smooth run of profile points; consecutive runs meet at hard edges (vertices not shared).
using ProfileRun = std::vector<ProfilePoint>;

// Builds lathe profiles from straight and curved pieces, traversed with the solid on the left
// (going up the outside of a column, the solid is towards the axis). Each piece is its own run.
class ProfileBuilder {
public:
    explicit ProfileBuilder(glm::vec2 start) : cursor_(start) {}

    // A straight piece from the cursor to (r, y), with `segments` pieces (>= 1).
    ProfileBuilder& lineTo(float r, float y, int segments = 1);
    // A circular arc around `center` from the cursor's angle to `endAngle` (radians); convex
    // (a bead: normal points away from the centre) or concave (a cove: normal points to it).
    ProfileBuilder& arcTo(glm::vec2 center, float endAngle, bool convex, int segments);
    // A general curve p(t), t in [0, 1], p(0) == cursor; normals from its derivative.
    ProfileBuilder& curve(const std::function<glm::vec2(float)>& p, int segments);

    glm::vec2 cursor() const { return cursor_; }
    const std::vector<ProfileRun>& runs() const { return runs_; }

private:
    glm::vec2 cursor_;
    std::vector<ProfileRun> runs_;
};

// An orthonormal frame: origin plus axes. For a lathe, `axis` is the axis of revolution and
// `side` the direction of angle zero; for boxes the three axes are the box's edges.
struct Frame {
    glm::vec3 origin{0.0f};
    glm::vec3 side{1.0f, 0.0f, 0.0f};
    glm::vec3 axis{0.0f, 1.0f, 0.0f};
    glm::vec3 third() const { return glm::cross(side, axis); }
};

// A frame whose axis is `axis` (normalised here), with some perpendicular side.
Frame frameAlong(const glm::vec3& origin, const glm::vec3& axis);

class MeshBuilder {
public:
    explicit MeshBuilder(std::size_t materialCount);

    std::size_t materialCount() const { return buckets_.size(); }
    void setUvScale(std::uint32_t material, float repeatsPerMetre);
    float uvScale(std::uint32_t material) const;

    // Low level: a vertex of `material` (index local to that material) and a triangle of three
    // such indices, counter-clockwise.
    std::uint32_t addVertex(std::uint32_t material, const glm::vec3& position, const glm::vec3& normal,
                            const glm::vec2& uvMetres);
    void addTriangle(std::uint32_t material, std::uint32_t a, std::uint32_t b, std::uint32_t c);

    // A flat convex polygon (3 or 4 corners in cyclic order, either direction) facing `normal`.
    // UVs are a planar projection in world metres, so neighbouring faces tile continuously.
    void addFlatQuad(std::uint32_t material, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                     const glm::vec3& p3, const glm::vec3& normal);
    void addFlatTriangle(std::uint32_t material, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                         const glm::vec3& normal);

    // A box with per-face normals (flat shaded); `frame.origin` is its centre and halfExtents
    // run along side, axis and third(). Faces whose bit is clear in `faceMask` are left out
    // (bits: 0 -side, 1 +side, 2 -axis, 3 +axis, 4 -third, 5 +third).
    void addBox(std::uint32_t material, const Frame& frame, const glm::vec3& halfExtents,
                unsigned faceMask = 0x3f);
    // An axis-aligned box from its corners.
    void addBox(std::uint32_t material, const glm::vec3& min, const glm::vec3& max, unsigned faceMask = 0x3f);

    // A parametric surface sampled on an (nu + 1) x (nv + 1) grid of (s, t) in [0, 1]^2, smooth
    // shaded (grid vertices shared). Each quad faces the average of its vertex normals.
    void addGrid(std::uint32_t material, int nu, int nv, const std::function<SurfacePoint(float, float)>& surface);
    // The same on explicit parameter samples (each list at least two values, in order).
    void addGrid(std::uint32_t material, const std::vector<float>& s, const std::vector<float>& t,
                 const std::function<SurfacePoint(float, float)>& surface);

    // A surface of revolution of `runs` around frame.axis, `segments` around. Texture u wraps a
    // whole number of times around the largest radius.
    void addLathe(std::uint32_t material, const Frame& frame, const std::vector<ProfileRun>& runs, int segments);

    // A closed cylinder (or frustum) of `segments` sides along frame.axis, from 0 to height.
    void addCylinder(std::uint32_t material, const Frame& frame, float radiusBottom, float radiusTop, float height,
                     int segments, bool capBottom = true, bool capTop = true);

    void addSphere(std::uint32_t material, const glm::vec3& center, float radius, int slices, int stacks);

    std::size_t triangleCount() const;

    // Appends the geometry to scene.vertices/indices and one DrawRange per non-empty material,
    // in material order. Indices are absolute (into scene.vertices). Does not touch materials,
    // images or bounds.
    void writeTo(Scene& scene) const;

private:
    struct Bucket {
        std::vector<Vertex> vertices;
        std::vector<std::uint32_t> indices;
        float uvScale = 1.0f;
    };
    Bucket& bucket(std::uint32_t material);
    const Bucket& bucket(std::uint32_t material) const;
    // Adds the quad a-b-c-d (vertex indices), wound to face `facing`, dropping degenerate halves.
    void addQuadFacing(std::uint32_t material, std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d,
                       const glm::vec3& facing);

    std::vector<Bucket> buckets_;
};

}  // namespace ml
