#include "scenes/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/gtc/constants.hpp>

namespace ml {

namespace {

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    const float len = glm::length(v);
    return len > 1e-20f ? v / len : fallback;
}

// A triangle with edges of non-negligible length and a non-negligible angle between them.
bool isDegenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 e1 = b - a;
    const glm::vec3 e2 = c - a;
    const float l1 = glm::length(e1);
    const float l2 = glm::length(e2);
    if (l1 < 1e-7f || l2 < 1e-7f) return true;
    return glm::length(glm::cross(e1, e2)) <= 1e-6f * l1 * l2;
}

}  // namespace

// --- ProfileBuilder ---------------------------------------------------------------------------

ProfileBuilder& ProfileBuilder::lineTo(float r, float y, int segments) {
    segments = std::max(segments, 1);
    const glm::vec2 a = cursor_;
    const glm::vec2 b{r, y};
    const glm::vec2 d = b - a;
    // Solid on the left of the direction of travel, so the outward normal is on the right.
    const glm::vec2 n = glm::length(d) > 0.0f ? glm::normalize(glm::vec2(d.y, -d.x)) : glm::vec2(1.0f, 0.0f);
    ProfileRun run;
    for (int i = 0; i <= segments; ++i) {
        const glm::vec2 p = glm::mix(a, b, float(i) / float(segments));
        run.push_back({p.x, p.y, n});
    }
    runs_.push_back(std::move(run));
    cursor_ = b;
    return *this;
}

ProfileBuilder& ProfileBuilder::arcTo(glm::vec2 center, float endAngle, bool convex, int segments) {
    segments = std::max(segments, 1);
    const glm::vec2 d0 = cursor_ - center;
    const float radius = glm::length(d0);
    const float startAngle = std::atan2(d0.y, d0.x);
    ProfileRun run;
    for (int i = 0; i <= segments; ++i) {
        const float a = startAngle + (endAngle - startAngle) * float(i) / float(segments);
        const glm::vec2 dir{std::cos(a), std::sin(a)};
        const glm::vec2 p = i == 0 ? cursor_ : center + radius * dir;
        run.push_back({p.x, p.y, convex ? dir : -dir});
    }
    cursor_ = glm::vec2(run.back().r, run.back().y);
    runs_.push_back(std::move(run));
    return *this;
}

ProfileBuilder& ProfileBuilder::curve(const std::function<glm::vec2(float)>& p, int segments) {
    segments = std::max(segments, 1);
    const float h = 0.25f / float(segments);
    ProfileRun run;
    for (int i = 0; i <= segments; ++i) {
        const float t = float(i) / float(segments);
        const glm::vec2 q = i == 0 ? cursor_ : p(t);
        const glm::vec2 d = p(std::min(t + h, 1.0f)) - p(std::max(t - h, 0.0f));
        const glm::vec2 n = glm::length(d) > 0.0f ? glm::normalize(glm::vec2(d.y, -d.x)) : glm::vec2(1.0f, 0.0f);
        run.push_back({q.x, q.y, n});
    }
    cursor_ = glm::vec2(run.back().r, run.back().y);
    runs_.push_back(std::move(run));
    return *this;
}

// --- Frame ------------------------------------------------------------------------------------

Frame frameAlong(const glm::vec3& origin, const glm::vec3& axis) {
    const glm::vec3 a = glm::normalize(axis);
    const glm::vec3 helper = std::abs(a.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    Frame f;
    f.origin = origin;
    f.axis = a;
    f.side = glm::normalize(glm::cross(helper, a));
    return f;
}

// --- MeshBuilder ------------------------------------------------------------------------------

MeshBuilder::MeshBuilder(std::size_t materialCount) : buckets_(materialCount) {}

MeshBuilder::Bucket& MeshBuilder::bucket(std::uint32_t material) {
    if (material >= buckets_.size()) throw std::out_of_range("MeshBuilder: material index out of range");
    return buckets_[material];
}

const MeshBuilder::Bucket& MeshBuilder::bucket(std::uint32_t material) const {
    if (material >= buckets_.size()) throw std::out_of_range("MeshBuilder: material index out of range");
    return buckets_[material];
}

void MeshBuilder::setUvScale(std::uint32_t material, float repeatsPerMetre) { bucket(material).uvScale = repeatsPerMetre; }

float MeshBuilder::uvScale(std::uint32_t material) const { return bucket(material).uvScale; }

std::uint32_t MeshBuilder::addVertex(std::uint32_t material, const glm::vec3& position, const glm::vec3& normal,
                                     const glm::vec2& uvMetres) {
    Bucket& b = bucket(material);
    Vertex v;
    v.position = position;
    v.normal = safeNormalize(normal, glm::vec3(0.0f, 1.0f, 0.0f));
    v.uv = uvMetres * b.uvScale;
    b.vertices.push_back(v);
    return static_cast<std::uint32_t>(b.vertices.size() - 1);
}

void MeshBuilder::addTriangle(std::uint32_t material, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    Bucket& bk = bucket(material);
    bk.indices.insert(bk.indices.end(), {a, b, c});
}

void MeshBuilder::addQuadFacing(std::uint32_t material, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                                std::uint32_t d, const glm::vec3& facing) {
    Bucket& bk = bucket(material);
    const glm::vec3& pa = bk.vertices[a].position;
    const glm::vec3& pb = bk.vertices[b].position;
    const glm::vec3& pc = bk.vertices[c].position;
    const glm::vec3& pd = bk.vertices[d].position;
    // The cross product of the diagonals is the quad's area normal, also when one edge collapses.
    if (glm::dot(glm::cross(pc - pa, pd - pb), facing) < 0.0f) std::swap(b, d);
    const glm::vec3& qb = bk.vertices[b].position;
    const glm::vec3& qd = bk.vertices[d].position;
    if (!isDegenerate(pa, qb, pc)) bk.indices.insert(bk.indices.end(), {a, b, c});
    if (!isDegenerate(pa, pc, qd)) bk.indices.insert(bk.indices.end(), {a, c, d});
}

namespace {

// Orthonormal texture axes (u, v) of a plane with normal n: v follows world up on walls and
// world -z on floors and ceilings; u completes a right-handed (u, v, n).
void planarAxes(const glm::vec3& n, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 ref = std::abs(n.y) > 0.7f ? glm::vec3(0.0f, 0.0f, -1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    v = glm::normalize(ref - n * glm::dot(ref, n));
    u = glm::cross(v, n);
}

}  // namespace

void MeshBuilder::addFlatQuad(std::uint32_t material, const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                              const glm::vec3& p3, const glm::vec3& normal) {
    const glm::vec3 n = glm::normalize(normal);
    glm::vec3 tu, tv;
    planarAxes(n, tu, tv);
    auto vert = [&](const glm::vec3& p) {
        return addVertex(material, p, n, glm::vec2(glm::dot(p, tu), glm::dot(p, tv)));
    };
    const std::uint32_t a = vert(p0), b = vert(p1), c = vert(p2), d = vert(p3);
    addQuadFacing(material, a, b, c, d, n);
}

void MeshBuilder::addFlatTriangle(std::uint32_t material, const glm::vec3& p0, const glm::vec3& p1,
                                  const glm::vec3& p2, const glm::vec3& normal) {
    if (isDegenerate(p0, p1, p2)) return;
    const glm::vec3 n = glm::normalize(normal);
    glm::vec3 tu, tv;
    planarAxes(n, tu, tv);
    auto vert = [&](const glm::vec3& p) {
        return addVertex(material, p, n, glm::vec2(glm::dot(p, tu), glm::dot(p, tv)));
    };
    const std::uint32_t a = vert(p0), b = vert(p1), c = vert(p2);
    if (glm::dot(glm::cross(p1 - p0, p2 - p0), n) >= 0.0f)
        addTriangle(material, a, b, c);
    else
        addTriangle(material, a, c, b);
}

void MeshBuilder::addBox(std::uint32_t material, const Frame& frame, const glm::vec3& halfExtents, unsigned faceMask) {
    const glm::vec3 axes[3] = {frame.side * halfExtents.x, frame.axis * halfExtents.y, frame.third() * halfExtents.z};
    for (int k = 0; k < 3; ++k) {
        const glm::vec3& a = axes[(k + 1) % 3];
        const glm::vec3& b = axes[(k + 2) % 3];
        for (int sign = 0; sign < 2; ++sign) {
            if (!(faceMask & (1u << (2 * k + sign)))) continue;
            const glm::vec3 out = sign ? axes[k] : -axes[k];
            const glm::vec3 c = frame.origin + out;
            addFlatQuad(material, c - a - b, c + a - b, c + a + b, c - a + b, out);
        }
    }
}

void MeshBuilder::addBox(std::uint32_t material, const glm::vec3& min, const glm::vec3& max, unsigned faceMask) {
    Frame f;
    f.origin = 0.5f * (min + max);
    addBox(material, f, 0.5f * (max - min), faceMask);
}

void MeshBuilder::addGrid(std::uint32_t material, int nu, int nv,
                          const std::function<SurfacePoint(float, float)>& surface) {
    nu = std::max(nu, 1);
    nv = std::max(nv, 1);
    std::vector<float> s(nu + 1), t(nv + 1);
    for (int i = 0; i <= nu; ++i) s[i] = float(i) / float(nu);
    for (int j = 0; j <= nv; ++j) t[j] = float(j) / float(nv);
    addGrid(material, s, t, surface);
}

void MeshBuilder::addGrid(std::uint32_t material, const std::vector<float>& s, const std::vector<float>& t,
                          const std::function<SurfacePoint(float, float)>& surface) {
    if (s.size() < 2 || t.size() < 2) return;
    const std::size_t nu = s.size(), nv = t.size();
    std::vector<std::uint32_t> idx(nu * nv);
    std::vector<glm::vec3> normals(nu * nv);
    for (std::size_t j = 0; j < nv; ++j) {
        for (std::size_t i = 0; i < nu; ++i) {
            const SurfacePoint p = surface(s[i], t[j]);
            idx[j * nu + i] = addVertex(material, p.position, p.normal, p.uv);
            normals[j * nu + i] = bucket(material).vertices[idx[j * nu + i]].normal;
        }
    }
    for (std::size_t j = 0; j + 1 < nv; ++j) {
        for (std::size_t i = 0; i + 1 < nu; ++i) {
            const std::size_t k00 = j * nu + i, k10 = k00 + 1, k01 = k00 + nu, k11 = k01 + 1;
            const glm::vec3 facing = normals[k00] + normals[k10] + normals[k11] + normals[k01];
            addQuadFacing(material, idx[k00], idx[k10], idx[k11], idx[k01], facing);
        }
    }
}

void MeshBuilder::addLathe(std::uint32_t material, const Frame& frame, const std::vector<ProfileRun>& runs,
                           int segments) {
    segments = std::max(segments, 3);
    float rMax = 0.0f;
    for (const ProfileRun& run : runs)
        for (const ProfilePoint& p : run) rMax = std::max(rMax, p.r);
    // Whole texture repeats around, so the seam at angle 2 pi matches angle 0.
    const float scale = uvScale(material);
    const float repeats = std::max(1.0f, std::round(glm::two_pi<float>() * rMax * scale));
    const float uAround = scale > 0.0f ? repeats / scale : 1.0f;
    const glm::vec3 third = frame.third();

    std::vector<glm::vec2> trig(segments + 1);
    for (int j = 0; j <= segments; ++j) {
        const float a = glm::two_pi<float>() * float(j % segments) / float(segments);
        trig[j] = {std::cos(a), std::sin(a)};
    }
    std::vector<float> s(segments + 1);
    for (int j = 0; j <= segments; ++j) s[j] = float(j);

    float arcLength = 0.0f;  // texture v runs along the profile, continuous across runs
    for (const ProfileRun& run : runs) {
        if (run.size() < 2) continue;
        std::vector<float> vAt(run.size());
        vAt[0] = arcLength;
        for (std::size_t k = 1; k < run.size(); ++k)
            vAt[k] = vAt[k - 1] + glm::length(glm::vec2(run[k].r - run[k - 1].r, run[k].y - run[k - 1].y));
        arcLength = vAt.back();
        std::vector<float> t(run.size());
        for (std::size_t k = 0; k < run.size(); ++k) t[k] = float(k);
        addGrid(material, s, t, [&](float sj, float tk) {
            const int j = int(sj), k = int(tk);
            const ProfilePoint& p = run[k];
            const glm::vec3 radial = trig[j].x * frame.side + trig[j].y * third;
            SurfacePoint sp;
            sp.position = frame.origin + p.r * radial + p.y * frame.axis;
            sp.normal = p.normal.x * radial + p.normal.y * frame.axis;
            sp.uv = {uAround * float(j) / float(segments), vAt[k]};
            return sp;
        });
    }
}

void MeshBuilder::addCylinder(std::uint32_t material, const Frame& frame, float radiusBottom, float radiusTop,
                              float height, int segments, bool capBottom, bool capTop) {
    ProfileBuilder pb({capBottom ? 0.0f : radiusBottom, 0.0f});
    if (capBottom) pb.lineTo(radiusBottom, 0.0f);
    pb.lineTo(radiusTop, height);
    if (capTop) pb.lineTo(0.0f, height);
    addLathe(material, frame, pb.runs(), segments);
}

void MeshBuilder::addSphere(std::uint32_t material, const glm::vec3& center, float radius, int slices, int stacks) {
    slices = std::max(slices, 3);
    stacks = std::max(stacks, 2);
    const float scale = uvScale(material);
    const float repeats = std::max(1.0f, std::round(glm::two_pi<float>() * radius * scale));
    const float uAround = scale > 0.0f ? repeats / scale : 1.0f;
    addGrid(material, slices, stacks, [&](float s, float t) {
        const float phi = glm::two_pi<float>() * (s >= 1.0f ? 0.0f : s);
        const float theta = glm::pi<float>() * t;
        const float st = (t <= 0.0f || t >= 1.0f) ? 0.0f : std::sin(theta);
        const float ct = t <= 0.0f ? 1.0f : (t >= 1.0f ? -1.0f : std::cos(theta));
        const glm::vec3 dir{st * std::cos(phi), ct, st * std::sin(phi)};
        SurfacePoint p;
        p.position = center + radius * dir;
        p.normal = dir;
        p.uv = {uAround * s, radius * theta};
        return p;
    });
}

std::size_t MeshBuilder::triangleCount() const {
    std::size_t n = 0;
    for (const Bucket& b : buckets_) n += b.indices.size() / 3;
    return n;
}

void MeshBuilder::writeTo(Scene& scene) const {
    for (std::size_t m = 0; m < buckets_.size(); ++m) {
        const Bucket& b = buckets_[m];
        if (b.indices.empty()) continue;
        const std::size_t base = scene.vertices.size();
        if (base + b.vertices.size() > std::numeric_limits<std::uint32_t>::max())
            throw SceneError("procedural scene: more than 2^32 vertices");
        DrawRange range;
        range.firstIndex = static_cast<std::uint32_t>(scene.indices.size());
        range.indexCount = static_cast<std::uint32_t>(b.indices.size());
        range.material = static_cast<std::uint32_t>(m);
        scene.vertices.insert(scene.vertices.end(), b.vertices.begin(), b.vertices.end());
        for (std::uint32_t i : b.indices) scene.indices.push_back(static_cast<std::uint32_t>(base) + i);
        scene.draws.push_back(range);
    }
}

}  // namespace ml
