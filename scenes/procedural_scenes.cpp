#include "scenes/procedural_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "scenes/mesh_builder.h"
#include "scenes/procedural_textures.h"
#include "scenes/tangent_frames.h"

namespace ml {

namespace {

constexpr float kPi = glm::pi<float>();

// --- Materials ----------------------------------------------------------------------------------

struct MaterialSpec {
    const char* name;
    glm::vec4 baseColor;
    int texture;          // index into the scene's images, or -1
    float metallic;
    float roughness;
    float metresPerRepeat;  // world size of one texture repeat
    // Drawn without back-face culling: thin sheets whose open edges show their back faces.
    bool doubleSided = false;
};

// Adds the materials to the scene and sets the builder's texture scale for each.
void addMaterials(Scene& scene, MeshBuilder& mb, const std::vector<MaterialSpec>& specs) {
    for (std::size_t i = 0; i < specs.size(); ++i) {
        const MaterialSpec& s = specs[i];
        Material m;
        m.name = s.name;
        m.baseColorFactor = s.baseColor;
        m.baseColorTexture.image = s.texture;
        m.metallic = s.metallic;
        m.roughness = s.roughness;
        m.doubleSided = s.doubleSided;
        scene.materials.push_back(m);
        mb.setUvScale(static_cast<std::uint32_t>(i), 1.0f / s.metresPerRepeat);
    }
}

// Segment counts scaled by the detail level: each of a surface's two directions gets
// sqrt(detail) times its base count (at least `min`), so triangles grow about linearly with detail.
struct Tess {
    float detail = 1.0f;
    int sq(float base, int min) const { return std::max(min, int(std::lround(base * std::sqrt(detail)))); }
};

// --- The atrium's layout (metres) ---------------------------------------------------------------
//
// x runs along the courtyard, z across it, y up. The end walls' inner faces are at x = +-17.4,
// the back walls' at z = +-7.7; the arcades stand on z = +-5 with a bay of 4 m (columns at
// x = -16, -12, ..., 16), two storeys, the roof at 11.4-12 m.

enum AtriumMaterial : std::uint32_t {
    kFloor,
    kColumnMarble,
    kStone,
    kPlaster,
    kFabricRed,
    kFabricGreen,
    kFabricBlue,
    kBronze,
    kWater,
    kWood,
    kPolishedMarble,
    kGlazedOchre,
    kDarkStone,
    kFoliage,      // alpha-tested (MASK) leaves on cross quads in the planters
    kLanternGlow,  // emissive lantern globes on bronze posts
    kGlassTeal,    // glass screens across the courtyard (BLEND), one material each so each is
    kGlassRose,    // its own draw range and they blend back to front as screens
    kGlassAmber,
    kAtriumMaterialCount
};

enum AtriumImage : int {
    kImgFloor,
    kImgStone,
    kImgMarble,
    kImgPlaster,
    kImgFabric,
    kImgWood,
    kImgFloorNormal,
    kImgStoneNormal,
    kImgFoliage,
    kAtriumImageCount
};

constexpr float kEndInner = 17.4f;   // end walls, inner face
constexpr float kEndOuter = 18.0f;
constexpr float kBackInner = 7.7f;   // back walls, inner face
constexpr float kBackOuter = 8.0f;
constexpr float kArcadeZ = 5.0f;     // column axes
constexpr float kBandHalf = 0.3f;    // half the thickness of the walls over the arches
constexpr float kBay = 4.0f;
constexpr int kBays = 8;
constexpr float kFirstColumnX = -16.0f;
constexpr float kGalleryCeiling = 5.75f;  // underside of the first floor's slab
constexpr float kRoofBottom = 11.4f;
constexpr float kRoofTop = 11.75f;
constexpr float kHeight = 12.0f;
constexpr float kCorniceZ = 4.45f;        // front of the string course under the first floor
constexpr float kRoofFrontZ = 4.4f;

struct ColumnStyle {
    float radius;        // shaft radius at the bottom
    float plinthHalf;    // half width of the square plinth
    float plinthHeight;
    float abacusHalf;    // half width of the square slab on top of the capital
    float abacusHeight;
};

struct Storey {
    float floorY;
    float springY;  // where the arches spring (top of the columns)
    float topY;     // top of the wall over the arches
    ColumnStyle column;
};

const Storey kLower{0.0f, 4.0f, 6.0f, {0.36f, 0.49f, 0.30f, 0.45f, 0.20f}};
const Storey kUpper{6.0f, 9.0f, kRoofBottom, {0.28f, 0.38f, 0.20f, 0.36f, 0.15f}};

float columnX(int k) { return kFirstColumnX + kBay * float(k); }
float bayCenterX(int b) { return kFirstColumnX + kBay * (float(b) + 0.5f); }

// --- Walls with arched openings -----------------------------------------------------------------

// A wall's front face: a point on it, u along the wall, v up, n its outward normal. Points at
// depth w < 0 lie inside the wall.
struct WallFrame {
    glm::vec3 origin;
    glm::vec3 u;
    glm::vec3 v;
    glm::vec3 n;
    glm::vec3 at(float a, float b, float w = 0.0f) const { return origin + a * u + b * v + w * n; }
};

// A round-arched opening: vertical jambs from `bottom` to `spring`, then a semicircle.
struct ArchedOpening {
    float center;  // u of its axis
    float radius;  // half its width, and the arch's radius
    float bottom;  // v of its sill
    float spring;  // v where the arch springs
    float depth;   // depth of the reveals; less than the wall's thickness leaves a recess
};

void wallRect(MeshBuilder& mb, std::uint32_t mat, const WallFrame& f, float u0, float u1, float v0, float v1, float w,
              const glm::vec3& normal) {
    if (u1 - u0 <= 1e-4f || v1 - v0 <= 1e-4f) return;
    mb.addFlatQuad(mat, f.at(u0, v0, w), f.at(u1, v0, w), f.at(u1, v1, w), f.at(u0, v1, w), normal);
}

// Angles along the arch, 0 (the u+ side) to pi, with the directions of the panel's top corners
// added so the ring between arch and panel edge is made of flat convex quads.
std::vector<float> archAngles(int segments, const ArchedOpening& o, float u0, float u1, float v1) {
    std::vector<float> a;
    for (int k = 0; k <= segments; ++k) a.push_back(kPi * float(k) / float(segments));
    a.push_back(std::atan2(v1 - o.spring, u1 - o.center));
    a.push_back(std::atan2(v1 - o.spring, u0 - o.center));
    std::sort(a.begin(), a.end());
    std::vector<float> out;
    for (float x : a)
        if (out.empty() || x - out.back() > 1e-3f) out.push_back(x);
    out.back() = kPi;
    return out;
}

// Where the ray from the arch's centre at angle theta leaves the panel [u0, u1] x [spring, v1].
glm::vec2 rayToPanel(float theta, const ArchedOpening& o, float u0, float u1, float v1) {
    const glm::vec2 d{std::cos(theta), std::sin(theta)};
    float t = std::numeric_limits<float>::max();
    if (d.x > 1e-6f) t = std::min(t, (u1 - o.center) / d.x);
    if (d.x < -1e-6f) t = std::min(t, (u0 - o.center) / d.x);
    if (d.y > 1e-6f) t = std::min(t, (v1 - o.spring) / d.y);
    glm::vec2 p = glm::vec2(o.center, o.spring) + t * d;
    p.x = std::clamp(p.x, u0, u1);
    p.y = std::min(p.y, v1);
    return p;
}

// A wall panel [u0, u1] x [v0, v1] of the given thickness with one arched opening through it (or
// a recess into it), its reveals (jambs, sill, the arch's underside) and, for a recess, the panel
// at its back. backFace adds the wall's other side.
void archedWall(MeshBuilder& mb, std::uint32_t faceMat, std::uint32_t revealMat, const WallFrame& f, float u0,
                float u1, float v0, float v1, const ArchedOpening& o, float thickness, bool backFace, int segments) {
    const bool through = o.depth >= thickness;
    const float d = std::min(o.depth, thickness);
    const float uc = o.center, r = o.radius, vs = o.spring;
    const std::vector<float> angles = archAngles(segments, o, u0, u1, v1);
    auto arc = [&](float a) { return glm::vec2(uc + r * std::cos(a), vs + r * std::sin(a)); };

    auto face = [&](float w, const glm::vec3& normal, bool withHole) {
        if (!withHole) {
            wallRect(mb, faceMat, f, u0, u1, v0, v1, w, normal);
            return;
        }
        wallRect(mb, faceMat, f, u0, u1, v0, o.bottom, w, normal);
        wallRect(mb, faceMat, f, u0, uc - r, o.bottom, vs, w, normal);
        wallRect(mb, faceMat, f, uc + r, u1, o.bottom, vs, w, normal);
        for (std::size_t k = 0; k + 1 < angles.size(); ++k) {
            const glm::vec2 a0 = arc(angles[k]), a1 = arc(angles[k + 1]);
            const glm::vec2 b0 = rayToPanel(angles[k], o, u0, u1, v1), b1 = rayToPanel(angles[k + 1], o, u0, u1, v1);
            mb.addFlatQuad(faceMat, f.at(a0.x, a0.y, w), f.at(b0.x, b0.y, w), f.at(b1.x, b1.y, w), f.at(a1.x, a1.y, w),
                           normal);
        }
    };
    face(0.0f, f.n, true);
    if (backFace) face(-thickness, -f.n, through);

    // Reveals: jambs face into the opening, the sill faces up, the arch's underside faces its centre.
    if (vs > o.bottom) {
        mb.addFlatQuad(revealMat, f.at(uc - r, o.bottom, 0.0f), f.at(uc - r, vs, 0.0f), f.at(uc - r, vs, -d),
                       f.at(uc - r, o.bottom, -d), f.u);
        mb.addFlatQuad(revealMat, f.at(uc + r, o.bottom, 0.0f), f.at(uc + r, vs, 0.0f), f.at(uc + r, vs, -d),
                       f.at(uc + r, o.bottom, -d), -f.u);
    }
    if (o.bottom > v0 || !through) {
        mb.addFlatQuad(revealMat, f.at(uc - r, o.bottom, 0.0f), f.at(uc + r, o.bottom, 0.0f),
                       f.at(uc + r, o.bottom, -d), f.at(uc - r, o.bottom, -d), f.v);
    }
    mb.addGrid(revealMat, angles, {0.0f, -d}, [&](float a, float w) {
        const glm::vec2 p = arc(a);
        SurfacePoint sp;
        sp.position = f.at(p.x, p.y, w);
        sp.normal = -(std::cos(a) * f.u + std::sin(a) * f.v);
        sp.uv = {a * r, w};
        return sp;
    });
    if (!through) {
        wallRect(mb, revealMat, f, uc - r, uc + r, o.bottom, vs, -d, f.n);
        const glm::vec3 c = f.at(uc, vs, -d);
        for (std::size_t k = 0; k + 1 < angles.size(); ++k) {
            const glm::vec2 a0 = arc(angles[k]), a1 = arc(angles[k + 1]);
            mb.addFlatTriangle(revealMat, c, f.at(a0.x, a0.y, -d), f.at(a1.x, a1.y, -d), f.n);
        }
    }
}

// A half-round moulding (archivolt) following an arch on the wall's front face.
void archBead(MeshBuilder& mb, std::uint32_t mat, const WallFrame& f, const ArchedOpening& o, float ringRadius,
              float beadRadius, int along, int around) {
    mb.addGrid(mat, along, around, [&](float s, float t) {
        const float theta = kPi * s, alpha = kPi * t;
        const glm::vec3 radial = std::cos(theta) * f.u + std::sin(theta) * f.v;
        const float rr = ringRadius + beadRadius * std::cos(alpha);
        SurfacePoint sp;
        sp.position = f.at(o.center, o.spring, 0.0f) + rr * radial + beadRadius * std::sin(alpha) * f.n;
        sp.normal = std::cos(alpha) * radial + std::sin(alpha) * f.n;
        sp.uv = {theta * ringRadius, alpha * beadRadius};
        return sp;
    });
}

// --- Columns, balusters, banners ------------------------------------------------------------------

// A column on a square plinth: a lathed base (two tori), a tapering shaft, an astragal, an ovolo
// capital, and a square abacus whose top is at springY.
void column(MeshBuilder& mb, const Tess& tess, const glm::vec3& base, float springY, const ColumnStyle& cs) {
    const float R = cs.radius, Rt = 0.86f * R;
    const float y0 = cs.plinthHeight;
    const float yTop = springY - base.y - cs.abacusHeight;  // bottom of the abacus, relative to base
    const float tb = 0.12f * R, ts = 0.07f * R, ta = 0.09f * R;
    const float echinusH = 0.7f * R, neck = 0.25f * R;
    const float rE = 0.92f * cs.abacusHalf;
    const int arcSeg = tess.sq(6.0f, 2);

    mb.addBox(kStone, glm::vec3(base.x - cs.plinthHalf, base.y, base.z - cs.plinthHalf),
              glm::vec3(base.x + cs.plinthHalf, base.y + cs.plinthHeight, base.z + cs.plinthHalf), 0x3fu & ~0x4u);
    mb.addBox(kStone, glm::vec3(base.x - cs.abacusHalf, springY - cs.abacusHeight, base.z - cs.abacusHalf),
              glm::vec3(base.x + cs.abacusHalf, springY, base.z + cs.abacusHalf));  // closed: the wall above is narrower

    const float yS0 = y0 + 2.0f * tb + 2.0f * ts;
    const float yS1 = yTop - echinusH - neck - 2.0f * ta;
    const float yE0 = yS1 + 2.0f * ta + neck;
    ProfileBuilder pb({R + tb, y0});
    pb.arcTo({R + tb, y0 + tb}, 0.5f * kPi, true, arcSeg);
    pb.lineTo(1.05f * R, y0 + 2.0f * tb);
    pb.arcTo({1.05f * R, y0 + 2.0f * tb + ts}, 0.5f * kPi, true, arcSeg);
    pb.lineTo(R, yS0);
    pb.curve([=](float t) { return glm::vec2(R - (R - Rt) * t * t, yS0 + t * (yS1 - yS0)); }, tess.sq(4.0f, 1));
    pb.arcTo({Rt, yS1 + ta}, 0.5f * kPi, true, arcSeg);
    pb.lineTo(Rt, yE0);
    pb.curve(
        [=](float t) {
            const float a = 0.5f * kPi * t;
            return glm::vec2(Rt + (rE - Rt) * std::sin(a), yE0 + (yTop - yE0) * (1.0f - std::cos(a)));
        },
        tess.sq(6.0f, 2));
    Frame frame;
    frame.origin = base;
    mb.addLathe(kColumnMarble, frame, pb.runs(), tess.sq(26.0f, 8));
}

// A vase-shaped baluster from y0 to y0 + height.
void baluster(MeshBuilder& mb, const Tess& tess, const glm::vec3& base, float height) {
    auto radius = [](float t) {
        const float bulb = std::exp(-((t - 0.32f) / 0.2f) * ((t - 0.32f) / 0.2f));
        const float top = std::max(0.0f, (t - 0.8f) / 0.2f);
        return 0.032f + 0.042f * bulb + 0.02f * top * top;
    };
    ProfileBuilder pb({radius(0.0f), 0.0f});
    pb.curve([=](float t) { return glm::vec2(radius(t), t * height); }, tess.sq(8.0f, 3));
    Frame frame;
    frame.origin = base;
    mb.addLathe(kStone, frame, pb.runs(), tess.sq(8.0f, 4));
}

// A banner hanging from a rod in front of an arcade: folds, a pointed lower edge, two sheets a
// few millimetres apart so it reads from both sides.
void banner(MeshBuilder& mb, const Tess& tess, std::uint32_t mat, float cx, float zFace, float toward, float yTop,
            float width, float height, float point, int folds) {
    auto pos = [=](float s, float t) {
        const float x = cx + (s - 0.5f) * width;
        const float length = height + point * (1.0f - std::abs(2.0f * s - 1.0f));
        const float y = yTop - t * length;
        const float amp = 0.03f + 0.06f * t;
        const float fold = amp * std::sin(glm::two_pi<float>() * float(folds) * s + 0.8f * t);
        const float billow = 0.06f * std::sin(kPi * s) * t;
        return glm::vec3(x, y, zFace + toward * (fold + billow));
    };
    const float h = 1e-3f;
    for (float sheet : {1.0f, -1.0f}) {
        mb.addGrid(mat, tess.sq(16.0f, 4), tess.sq(24.0f, 6), [&](float s, float t) {
            const glm::vec3 ds = pos(std::min(s + h, 1.0f), t) - pos(std::max(s - h, 0.0f), t);
            const glm::vec3 dt = pos(s, std::min(t + h, 1.0f)) - pos(s, std::max(t - h, 0.0f));
            // cross(ds, dt) points to -z (s runs along +x, t down): turn it towards the courtyard.
            const glm::vec3 n = glm::normalize(glm::cross(ds, dt)) * (-toward) * sheet;
            SurfacePoint sp;
            sp.position = pos(s, t) + 0.004f * n;
            sp.normal = n;
            sp.uv = {sp.position.x, sp.position.y};
            return sp;
        });
    }
    // The rod it hangs from, with a ball at each end and two brackets back to the wall.
    const float rodHalf = 0.5f * width + 0.12f;
    Frame rod = frameAlong(glm::vec3(cx - rodHalf, yTop + 0.02f, zFace), glm::vec3(1.0f, 0.0f, 0.0f));
    mb.addCylinder(kBronze, rod, 0.022f, 0.022f, 2.0f * rodHalf, tess.sq(10.0f, 5), false, false);
    for (float sx : {-1.0f, 1.0f}) {
        mb.addSphere(kBronze, glm::vec3(cx + sx * rodHalf, yTop + 0.02f, zFace), 0.045f, tess.sq(10.0f, 6),
                     tess.sq(6.0f, 4));
        const float bx = cx + sx * (rodHalf - 0.06f);
        const float zWall = zFace - toward * (kArcadeZ - kBandHalf - std::abs(zFace));
        const float zMin = std::min(zFace, zWall), zMax = std::max(zFace, zWall);
        mb.addBox(kBronze, glm::vec3(bx - 0.015f, yTop + 0.005f, zMin), glm::vec3(bx + 0.015f, yTop + 0.035f, zMax));
    }
}

// --- The atrium's parts ---------------------------------------------------------------------------

void addArcade(MeshBuilder& mb, const Tess& tess, float side, const Storey& st) {
    const float thickness = 2.0f * kBandHalf;
    const WallFrame f{glm::vec3(0.0f, 0.0f, side * (kArcadeZ - kBandHalf)), glm::vec3(1.0f, 0.0f, 0.0f),
                      glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, -side)};
    const float r = 0.5f * kBay - st.column.abacusHalf;
    for (int b = 0; b < kBays; ++b) {
        const float c = bayCenterX(b);
        const ArchedOpening o{c, r, st.springY, st.springY, thickness};
        archedWall(mb, kStone, kStone, f, c - 0.5f * kBay, c + 0.5f * kBay, st.springY, st.topY, o, thickness, true,
                   tess.sq(22.0f, 6));
        archBead(mb, kColumnMarble, f, o, r + 0.13f, 0.06f, tess.sq(30.0f, 8), tess.sq(6.0f, 3));
    }
    // Solid ends between the last columns and the end walls.
    const float u0 = columnX(0), u1 = columnX(kBays);
    for (float w : {0.0f, -thickness}) {
        const glm::vec3 n = w == 0.0f ? f.n : -f.n;
        wallRect(mb, kStone, f, -kEndInner, u0, st.springY, st.topY, w, n);
        wallRect(mb, kStone, f, u1, kEndInner, st.springY, st.topY, w, n);
    }
    const float z0 = std::min(side * (kArcadeZ - kBandHalf), side * (kArcadeZ + kBandHalf));
    const float z1 = std::max(side * (kArcadeZ - kBandHalf), side * (kArcadeZ + kBandHalf));
    const float pierEnd = -columnX(0) + st.column.abacusHalf;  // the pier stops where the abacus begins
    mb.addBox(kStone, glm::vec3(-kEndInner, st.floorY, z0), glm::vec3(-pierEnd, st.springY, z1), 0x32u);
    mb.addBox(kStone, glm::vec3(pierEnd, st.floorY, z0), glm::vec3(kEndInner, st.springY, z1), 0x31u);
    for (int k = 0; k <= kBays; ++k)
        column(mb, tess, glm::vec3(columnX(k), st.floorY, side * kArcadeZ), st.springY, st.column);
}

void addBalustrade(MeshBuilder& mb, const Tess& tess, float side) {
    const float y0 = kUpper.floorY, railLow = 0.15f, railTop = 0.9f, railCap = 0.15f;
    const float z = side * kArcadeZ;
    for (int b = 0; b < kBays; ++b) {
        const float c = bayCenterX(b);
        const float x0 = c - 0.5f * kBay + kUpper.column.plinthHalf, x1 = c + 0.5f * kBay - kUpper.column.plinthHalf;
        // With their ends: the rail meets the round shaft, whose plinth is lower, so they show.
        mb.addBox(kStone, glm::vec3(x0, y0, z - 0.15f), glm::vec3(x1, y0 + railLow, z + 0.15f), 0x3bu);
        mb.addBox(kStone, glm::vec3(x0, y0 + railTop, z - 0.18f), glm::vec3(x1, y0 + railTop + railCap, z + 0.18f));
        for (int k = 0; k < 7; ++k)
            baluster(mb, tess, glm::vec3(c + 0.45f * float(k - 3), y0 + railLow, z), railTop - railLow);
    }
}

void addBackWall(MeshBuilder& mb, const Tess& tess, float side) {
    const float thickness = kBackOuter - kBackInner;
    const WallFrame f{glm::vec3(0.0f, 0.0f, side * kBackInner), glm::vec3(1.0f, 0.0f, 0.0f),
                      glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, -side)};
    const int seg = tess.sq(14.0f, 6);
    for (int b = 0; b < kBays; ++b) {
        const float c = bayCenterX(b);
        const float u0 = c - 0.5f * kBay, u1 = c + 0.5f * kBay;
        archedWall(mb, kPlaster, kStone, f, u0, u1, 0.0f, kGalleryCeiling, {c, 0.75f, 0.0f, 2.3f, 0.22f}, thickness,
                   false, seg);
        archedWall(mb, kPlaster, kStone, f, u0, u1, kUpper.floorY, kRoofBottom, {c, 0.6f, 7.2f, 8.7f, 0.22f},
                   thickness, false, seg);
    }
    for (auto [v0, v1] : {std::pair{0.0f, kGalleryCeiling}, std::pair{kUpper.floorY, kRoofBottom}}) {
        wallRect(mb, kPlaster, f, -kEndInner, columnX(0), v0, v1, 0.0f, f.n);
        wallRect(mb, kPlaster, f, columnX(kBays), kEndInner, v0, v1, 0.0f, f.n);
    }
    // Outside.
    wallRect(mb, kStone, f, -kEndOuter, kEndOuter, 0.0f, kRoofBottom, -thickness, -f.n);
}

void addEndWall(MeshBuilder& mb, const Tess& tess, float end) {
    const float thickness = kEndOuter - kEndInner;
    const WallFrame f{glm::vec3(end * kEndInner, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                      glm::vec3(-end, 0.0f, 0.0f)};
    const int seg = tess.sq(22.0f, 6);
    archedWall(mb, kStone, kStone, f, -kBackInner, kBackInner, 0.0f, kUpper.floorY, {0.0f, 1.5f, 0.0f, 3.2f, 0.5f},
               thickness, false, seg);
    archedWall(mb, kStone, kStone, f, -kBackInner, kBackInner, kUpper.floorY, kHeight, {0.0f, 1.1f, 7.0f, 9.4f, 0.4f},
               thickness, false, seg);
    // Outside, the top, and the ends of the top above the roof.
    wallRect(mb, kStone, f, -kBackOuter, kBackOuter, 0.0f, kHeight, -thickness, -f.n);
    const float xi = end * kEndInner, xo = end * kEndOuter;
    mb.addFlatQuad(kStone, {xi, kHeight, -kBackOuter}, {xo, kHeight, -kBackOuter}, {xo, kHeight, kBackOuter},
                   {xi, kHeight, kBackOuter}, {0.0f, 1.0f, 0.0f});
    for (float s : {-1.0f, 1.0f}) {
        const float z = s * kBackOuter;
        mb.addFlatQuad(kStone, {xi, kRoofTop, z}, {xo, kRoofTop, z}, {xo, kHeight, z}, {xi, kHeight, z},
                       {0.0f, 0.0f, s});
    }
}

// Floors, ceilings with beams, the string course, the roof and its parapet on one side.
void addFloorsAndRoof(MeshBuilder& mb, float side) {
    const glm::vec3 up{0.0f, 1.0f, 0.0f}, down{0.0f, -1.0f, 0.0f}, out{0.0f, 0.0f, side}, in{0.0f, 0.0f, -side};
    auto z = [side](float a) { return side * a; };
    auto hquad = [&](std::uint32_t mat, float x0, float x1, float za, float zb, float y, const glm::vec3& n) {
        mb.addFlatQuad(mat, {x0, y, z(za)}, {x1, y, z(za)}, {x1, y, z(zb)}, {x0, y, z(zb)}, n);
    };
    auto vquad = [&](std::uint32_t mat, float x0, float x1, float za, float y0, float y1, const glm::vec3& n) {
        mb.addFlatQuad(mat, {x0, y0, z(za)}, {x1, y0, z(za)}, {x1, y1, z(za)}, {x0, y1, z(za)}, n);
    };
    const float bandBack = kArcadeZ + kBandHalf, bandFront = kArcadeZ - kBandHalf;

    // First floor: walking surface (over the string course, the band and the slab) and its underside.
    hquad(kFloor, -kEndInner, kEndInner, kCorniceZ, kBackInner, kUpper.floorY, up);
    hquad(kWood, -kEndInner, kEndInner, bandBack, kBackInner, kGalleryCeiling, down);
    // String course: front and underside.
    vquad(kStone, -kEndInner, kEndInner, kCorniceZ, kUpper.floorY - 0.2f, kUpper.floorY, in);
    hquad(kStone, -kEndInner, kEndInner, kCorniceZ, bandFront, kUpper.floorY - 0.2f, down);
    // Roof slab: top, front, underside of its cornice, ends, outside; the upper gallery's ceiling.
    hquad(kStone, -kEndOuter, kEndOuter, kRoofFrontZ, kBackOuter, kRoofTop, up);
    vquad(kStone, -kEndInner, kEndInner, kRoofFrontZ, kRoofBottom, kRoofTop, in);
    hquad(kStone, -kEndInner, kEndInner, kRoofFrontZ, bandFront, kRoofBottom, down);
    vquad(kStone, -kEndOuter, kEndOuter, kBackOuter, kRoofBottom, kRoofTop, out);
    hquad(kWood, -kEndInner, kEndInner, bandBack, kBackInner, kRoofBottom, down);
    // Parapet on the roof's front edge.
    {
        const float za = std::min(z(kRoofFrontZ), z(bandFront)), zb = std::max(z(kRoofFrontZ), z(bandFront));
        mb.addBox(kStone, glm::vec3(-kEndInner, kRoofTop, za), glm::vec3(kEndInner, kHeight, zb), 0x38u);
    }
    // Beams under both galleries' ceilings.
    for (float ceiling : {kGalleryCeiling, kRoofBottom}) {
        for (int k = 0; k < 35; ++k) {
            const float x = -17.0f + float(k);
            const float za = std::min(z(bandBack), z(kBackInner)), zb = std::max(z(bandBack), z(kBackInner));
            mb.addBox(kWood, glm::vec3(x - 0.07f, ceiling - 0.18f, za), glm::vec3(x + 0.07f, ceiling, zb), 0x07u);
        }
    }
}

// The fountain: a stone basin with water, a bronze pedestal and bowl with water, a ball on top.
void addFountain(MeshBuilder& mb, const Tess& tess, const glm::vec3& at) {
    const int around = tess.sq(64.0f, 16);
    const int seg = tess.sq(10.0f, 3);
    Frame frame;
    frame.origin = at;
    const float rb = 2.2f;
    {
        ProfileBuilder pb({rb, 0.0f});
        pb.lineTo(rb, 0.45f);
        pb.arcTo({rb - 0.1f, 0.45f}, kPi, true, seg);
        pb.lineTo(rb - 0.2f, 0.15f);
        pb.lineTo(0.45f, 0.15f);
        mb.addLathe(kPolishedMarble, frame, pb.runs(), around);
    }
    {
        ProfileBuilder water({rb - 0.2f, 0.42f});
        water.lineTo(0.3f, 0.42f, 2);
        mb.addLathe(kWater, frame, water.runs(), around);
    }
    {
        auto stem = [](float t) { return 0.45f - 0.25f * t + 0.06f * std::sin(kPi * t); };
        ProfileBuilder pb({0.45f, 0.15f});
        pb.curve([&](float t) { return glm::vec2(stem(t), 0.15f + 1.05f * t); }, 2 * seg);
        pb.curve([](float t) { return glm::vec2(0.2f + 0.7f * std::sin(0.5f * kPi * t), 1.2f + 0.3f * t * t); }, seg);
        pb.arcTo({0.85f, 1.5f}, kPi, true, seg);
        pb.curve([](float t) { return glm::vec2(0.8f * (1.0f - t), 1.5f - 0.18f * std::sin(0.5f * kPi * t)); }, seg);
        mb.addLathe(kBronze, frame, pb.runs(), around);
    }
    {
        ProfileBuilder water({0.79f, 1.46f});
        water.lineTo(0.0f, 1.46f, 2);
        mb.addLathe(kWater, frame, water.runs(), around);
    }
    Frame spout = frame;
    spout.origin = at + glm::vec3(0.0f, 1.3f, 0.0f);
    mb.addCylinder(kBronze, spout, 0.05f, 0.04f, 0.35f, tess.sq(12.0f, 6), false, false);
    mb.addSphere(kBronze, at + glm::vec3(0.0f, 1.74f, 0.0f), 0.1f, tess.sq(20.0f, 8), tess.sq(10.0f, 4));
}

Frame yawed(const glm::vec3& center, float yaw) {
    Frame f;
    f.origin = center;
    f.side = glm::vec3(std::cos(yaw), 0.0f, -std::sin(yaw));
    return f;
}

void addCourtyardObjects(MeshBuilder& mb, const Tess& tess) {
    const int slices = tess.sq(36.0f, 10), stacks = tess.sq(18.0f, 6);
    const std::uint32_t sphereMats[4] = {kPolishedMarble, kGlazedOchre, kBronze, kPolishedMarble};
    int i = 0;
    for (float x : {-8.5f, 8.5f}) {
        for (float z : {-2.6f, 2.6f}) {
            mb.addBox(kDarkStone, glm::vec3(x - 0.4f, 0.0f, z - 0.4f), glm::vec3(x + 0.4f, 1.0f, z + 0.4f),
                      0x3fu & ~0x4u);
            mb.addSphere(sphereMats[i++], glm::vec3(x, 1.38f, z), 0.38f, slices, stacks);
        }
    }
    mb.addSphere(kPolishedMarble, glm::vec3(-12.5f, 0.75f, -1.8f), 0.75f, slices, stacks);
    mb.addSphere(kGlazedOchre, glm::vec3(12.8f, 0.55f, 2.2f), 0.55f, slices, stacks);
    // Crates.
    const unsigned noBottom = 0x3fu & ~0x4u;
    mb.addBox(kWood, yawed({11.8f, 0.5f, -2.6f}, 0.3f), {0.5f, 0.5f, 0.5f}, noBottom);
    mb.addBox(kWood, yawed({11.85f, 1.3f, -2.55f}, 0.9f), {0.3f, 0.3f, 0.3f}, noBottom);
    mb.addBox(kWood, yawed({13.2f, 0.35f, -3.1f}, -0.2f), {0.6f, 0.35f, 0.4f}, noBottom);
    // Stone benches.
    for (float x : {-4.5f, 4.5f}) {
        mb.addBox(kStone, glm::vec3(x - 1.0f, 0.35f, 3.3f), glm::vec3(x + 1.0f, 0.45f, 3.8f));
        mb.addBox(kStone, glm::vec3(x - 0.8f, 0.0f, 3.4f), glm::vec3(x - 0.6f, 0.35f, 3.7f), noBottom);
        mb.addBox(kStone, glm::vec3(x + 0.6f, 0.0f, 3.4f), glm::vec3(x + 0.8f, 0.35f, 3.7f), noBottom);
    }
}

// Planters in the courtyard's corners: a stone trough with a bush of three alpha-tested quads
// crossed at 60 degrees. Leaf normals lean up, so both faces of a quad light like foliage.
void addPlanters(MeshBuilder& mb) {
    const unsigned noBottom = 0x3fu & ~0x4u;
    for (float x : {-15.2f, 15.2f}) {
        for (float z : {-3.6f, 3.6f}) {
            mb.addBox(kDarkStone, glm::vec3(x - 0.5f, 0.0f, z - 0.5f), glm::vec3(x + 0.5f, 0.6f, z + 0.5f), noBottom);
            const float halfWidth = 0.75f, bottom = 0.45f, top = 2.1f;
            for (int k = 0; k < 3; ++k) {
                const float yaw = kPi / 3.0f * float(k) + 0.3f;
                const glm::vec3 across(std::cos(yaw), 0.0f, std::sin(yaw));
                const glm::vec3 facing(-across.z, 0.0f, across.x);
                const glm::vec3 n = glm::normalize(0.5f * facing + glm::vec3(0.0f, 1.0f, 0.0f));
                const glm::vec3 c(x, 0.0f, z);
                // The texture's v = 0 is the bush's top (uvScale 1 for this material: uv = uvMetres).
                const std::uint32_t a = mb.addVertex(kFoliage, c - halfWidth * across + glm::vec3(0, bottom, 0), n, {0.0f, 1.0f});
                const std::uint32_t b = mb.addVertex(kFoliage, c + halfWidth * across + glm::vec3(0, bottom, 0), n, {1.0f, 1.0f});
                const std::uint32_t d = mb.addVertex(kFoliage, c + halfWidth * across + glm::vec3(0, top, 0), n, {1.0f, 0.0f});
                const std::uint32_t e = mb.addVertex(kFoliage, c - halfWidth * across + glm::vec3(0, top, 0), n, {0.0f, 0.0f});
                mb.addTriangle(kFoliage, a, b, d);
                mb.addTriangle(kFoliage, a, d, e);
            }
        }
    }
}

// Lantern posts along the courtyard: bronze shafts with glowing globes. The globes are emissive:
// they glow in every method but light nothing (only the scene's point lights do).
void addLanterns(MeshBuilder& mb, const Tess& tess) {
    const int segments = tess.sq(16.0f, 8);
    for (float x : {-10.0f, -2.0f, 6.0f, 14.0f}) {
        for (float z : {-4.2f, 4.2f}) {
            mb.addCylinder(kBronze, frameAlong(glm::vec3(x, 0.0f, z), glm::vec3(0.0f, 1.0f, 0.0f)), 0.09f, 0.05f, 2.2f, segments,
                           /*capBottom=*/false);
            mb.addSphere(kLanternGlow, glm::vec3(x, 2.38f, z), 0.18f, segments, segments / 2 + 2);
        }
    }
}

// Three glass screens standing across the courtyard on bronze sills, one behind another seen
// down its length, so the transparent pass blends them over each other.
void addGlassScreens(MeshBuilder& mb) {
    const std::pair<float, std::uint32_t> screens[] = {{-6.0f, kGlassTeal}, {3.2f, kGlassRose}, {10.8f, kGlassAmber}};
    const float halfWidth = 1.7f, bottom = 0.12f, top = 2.9f;
    for (const auto& [x, glass] : screens) {
        mb.addBox(kBronze, glm::vec3(x - 0.06f, 0.0f, -halfWidth - 0.05f), glm::vec3(x + 0.06f, bottom, halfWidth + 0.05f), 0x3bu);
        mb.addFlatQuad(glass, {x, bottom, -halfWidth}, {x, bottom, halfWidth}, {x, top, halfWidth}, {x, top, -halfWidth},
                       {-1.0f, 0.0f, 0.0f});
    }
}

void addBanners(MeshBuilder& mb, const Tess& tess) {
    const std::uint32_t colours[3] = {kFabricRed, kFabricGreen, kFabricBlue};
    int n = 0;
    for (float side : {-1.0f, 1.0f}) {
        for (int b = (side < 0.0f ? 0 : 1); b < kBays; b += 2) {
            banner(mb, tess, colours[n % 3], bayCenterX(b), side * 4.3f, -side, 5.7f, 1.5f, 3.1f, 0.35f, 3);
            ++n;
        }
    }
}

std::vector<MaterialSpec> atriumMaterials() {
    std::vector<MaterialSpec> m(kAtriumMaterialCount);
    m[kFloor] = {"floor_tiles", {1.0f, 1.0f, 1.0f, 1.0f}, kImgFloor, 0.0f, 0.47f, 4.0f};
    m[kColumnMarble] = {"column_marble", {0.95f, 0.92f, 0.85f, 1.0f}, kImgMarble, 0.0f, 0.42f, 1.5f};
    m[kStone] = {"stone_blocks", {0.95f, 0.90f, 0.82f, 1.0f}, kImgStone, 0.0f, 0.55f, 2.4f};
    m[kPlaster] = {"plaster_wall", {1.0f, 0.95f, 0.88f, 1.0f}, kImgPlaster, 0.0f, 0.64f, 3.0f};
    m[kFabricRed] = {"fabric_red", {0.70f, 0.05f, 0.04f, 1.0f}, kImgFabric, 0.0f, 0.67f, 0.5f, true};
    m[kFabricGreen] = {"fabric_green", {0.06f, 0.40f, 0.10f, 1.0f}, kImgFabric, 0.0f, 0.67f, 0.5f, true};
    m[kFabricBlue] = {"fabric_blue", {0.05f, 0.12f, 0.55f, 1.0f}, kImgFabric, 0.0f, 0.67f, 0.5f, true};
    m[kBronze] = {"bronze", {0.62f, 0.42f, 0.20f, 1.0f}, -1, 1.0f, 0.35f, 1.0f};
    m[kWater] = {"water", {0.04f, 0.14f, 0.18f, 1.0f}, -1, 0.0f, 0.30f, 1.0f};
    m[kWood] = {"wood", {1.0f, 1.0f, 1.0f, 1.0f}, kImgWood, 0.0f, 0.58f, 2.0f};
    m[kPolishedMarble] = {"polished_marble", {1.0f, 1.0f, 1.0f, 1.0f}, kImgMarble, 0.0f, 0.38f, 1.0f};
    m[kGlazedOchre] = {"glazed_ochre", {0.80f, 0.45f, 0.08f, 1.0f}, -1, 0.0f, 0.40f, 1.0f};
    m[kDarkStone] = {"dark_stone", {0.30f, 0.29f, 0.27f, 1.0f}, kImgMarble, 0.0f, 0.45f, 1.0f};
    m[kFoliage] = {"foliage", {1.0f, 1.0f, 1.0f, 1.0f}, kImgFoliage, 0.0f, 0.75f, 1.0f, true};
    m[kLanternGlow] = {"lantern_glow", {0.95f, 0.85f, 0.65f, 1.0f}, -1, 0.0f, 0.3f, 1.0f};
    m[kGlassTeal] = {"glass_teal", {0.15f, 0.70f, 0.62f, 0.45f}, -1, 0.0f, 0.12f, 1.0f, true};
    m[kGlassRose] = {"glass_rose", {0.85f, 0.25f, 0.40f, 0.45f}, -1, 0.0f, 0.12f, 1.0f, true};
    m[kGlassAmber] = {"glass_amber", {0.95f, 0.55f, 0.10f, 0.50f}, -1, 0.0f, 0.12f, 1.0f, true};
    return m;
}

// The textures do not depend on the detail level: generated once per process (about 2.3 MB).
const std::vector<Image>& atriumImages() {
    static const std::vector<Image> images = [] {
        std::vector<Image> v(kAtriumImageCount);
        v[kImgFloor] = proctex::floorTiles(512);
        v[kImgStone] = proctex::stoneBlocks(256);
        v[kImgMarble] = proctex::marble(256);
        v[kImgPlaster] = proctex::plaster(256);
        v[kImgFabric] = proctex::fabric(256);
        v[kImgWood] = proctex::woodPlanks(256);
        v[kImgFloorNormal] = proctex::floorTilesNormal(512);
        v[kImgStoneNormal] = proctex::stoneBlocksNormal(256);
        v[kImgFoliage] = proctex::foliage(256);
        return v;
    }();
    return images;
}

constexpr float kMinDetail = 0.05f;
constexpr float kMaxDetail = 8.0f;

// A flat-shaded square of side `size` at y = 0, facing up.
void addGround(MeshBuilder& mb, std::uint32_t mat, float size) {
    const float h = 0.5f * size;
    mb.addFlatQuad(mat, {-h, 0.0f, -h}, {h, 0.0f, -h}, {h, 0.0f, h}, {-h, 0.0f, h}, {0.0f, 1.0f, 0.0f});
}

void finish(Scene& scene, const MeshBuilder& mb) {
    mb.writeTo(scene);
    computeBounds(scene);
}

}  // namespace

Scene makeAtrium(float detail) {
    if (!(detail > 0.0f)) throw SceneError("atrium: detail must be > 0");  // NaN fails the test too
    const Tess tess{std::clamp(detail, kMinDetail, kMaxDetail)};

    Scene scene;
    scene.name = "atrium";
    scene.images = atriumImages();

    MeshBuilder mb(kAtriumMaterialCount);
    addMaterials(scene, mb, atriumMaterials());
    // What the procedural specs do not say: normal maps (tiled as their colour maps), the
    // foliage's cut-out (clamped, so the bush's edges do not wrap), the lanterns' glow, the
    // screens' glass.
    scene.materials[kFloor].normalTexture.image = kImgFloorNormal;
    scene.materials[kStone].normalTexture.image = kImgStoneNormal;
    Sampler clamped;
    clamped.wrapS = clamped.wrapT = 0x812F;  // GL_CLAMP_TO_EDGE
    scene.samplers.push_back(clamped);
    Material& foliage = scene.materials[kFoliage];
    foliage.alphaMode = AlphaMode::Mask;
    foliage.alphaCutoff = 0.5f;
    foliage.baseColorTexture.sampler = 0;
    scene.materials[kLanternGlow].emissive = glm::vec3(1.0f, 0.62f, 0.28f) * 4.0f;
    for (std::uint32_t glass : {kGlassTeal, kGlassRose, kGlassAmber}) scene.materials[glass].alphaMode = AlphaMode::Blend;

    // The courtyard and gallery floor.
    mb.addFlatQuad(kFloor, {-kEndInner, 0.0f, -kBackInner}, {kEndInner, 0.0f, -kBackInner},
                   {kEndInner, 0.0f, kBackInner}, {-kEndInner, 0.0f, kBackInner}, {0.0f, 1.0f, 0.0f});
    for (float side : {-1.0f, 1.0f}) {
        addArcade(mb, tess, side, kLower);
        addArcade(mb, tess, side, kUpper);
        addBalustrade(mb, tess, side);
        addBackWall(mb, tess, side);
        addFloorsAndRoof(mb, side);
    }
    for (float end : {-1.0f, 1.0f}) addEndWall(mb, tess, end);
    addFountain(mb, tess, glm::vec3(0.0f));
    addCourtyardObjects(mb, tess);
    addPlanters(mb);
    addLanterns(mb, tess);
    addBanners(mb, tess);
    addGlassScreens(mb);

    finish(scene, mb);
    IndexRanges normalMapped;
    for (const DrawRange& d : scene.draws)
        if (scene.materials[d.material].normalTexture.present()) normalMapped.emplace_back(d.firstIndex, d.indexCount);
    generateTangents(scene, normalMapped, 0);
    // From the x = -17 end, above the ground-floor arches, down the length of the courtyard.
    scene.suggestedView = CameraPose{glm::vec3(-16.6f, 6.6f, 0.0f), glm::vec3(16.0f, 2.6f, 0.0f), 60.0f};
    return scene;
}

Scene makePlane() {
    Scene scene;
    scene.name = "plane";
    MeshBuilder mb(1);
    addMaterials(scene, mb, {{"white", {0.8f, 0.8f, 0.8f, 1.0f}, -1, 0.0f, 0.49f, 1.0f}});
    addGround(mb, 0, 20.0f);
    finish(scene, mb);
    scene.suggestedView = CameraPose{glm::vec3(0.0f, 10.0f, 14.0f), glm::vec3(0.0f), 60.0f};
    return scene;
}

Scene makeBoxes() {
    Scene scene;
    scene.name = "boxes";
    MeshBuilder mb(6);
    addMaterials(scene, mb,
                 {{"ground", {0.8f, 0.8f, 0.8f, 1.0f}, -1, 0.0f, 0.53f, 1.0f},
                  {"red", {0.75f, 0.08f, 0.06f, 1.0f}, -1, 0.0f, 0.49f, 1.0f},
                  {"green", {0.10f, 0.60f, 0.15f, 1.0f}, -1, 0.0f, 0.49f, 1.0f},
                  {"blue", {0.08f, 0.18f, 0.75f, 1.0f}, -1, 0.0f, 0.42f, 1.0f},
                  {"yellow", {0.85f, 0.70f, 0.10f, 1.0f}, -1, 0.0f, 0.45f, 1.0f},
                  {"white", {0.90f, 0.90f, 0.90f, 1.0f}, -1, 0.0f, 0.35f, 1.0f}});
    addGround(mb, 0, 20.0f);
    // Boxes stand on the ground; their bottoms are never seen and are left out.
    const unsigned noBottom = 0x3fu & ~0x4u;
    mb.addBox(1, yawed({-4.0f, 1.0f, -3.0f}, 0.0f), {1.0f, 1.0f, 1.0f}, noBottom);
    mb.addBox(2, yawed({3.0f, 1.5f, -2.5f}, 0.4f), {0.5f, 1.5f, 0.5f}, noBottom);
    mb.addBox(3, yawed({-2.5f, 0.5f, 3.5f}, -0.3f), {1.5f, 0.5f, 1.0f}, noBottom);
    mb.addBox(4, yawed({4.0f, 0.75f, 3.0f}, 0.52f), {0.75f, 0.75f, 0.75f}, noBottom);
    mb.addBox(5, yawed({0.5f, 0.4f, 0.0f}, 0.8f), {0.4f, 0.4f, 0.4f}, noBottom);
    finish(scene, mb);
    scene.suggestedView = CameraPose{glm::vec3(9.0f, 8.0f, 13.0f), glm::vec3(0.0f, 0.8f, 0.0f), 60.0f};
    return scene;
}

}  // namespace ml
