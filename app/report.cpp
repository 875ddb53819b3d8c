#include "app/report.h"

#include "glsl/include/bindings.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "renderer/scene/material_features.h"

namespace ml::app {

void printPassTimes(const std::vector<PassTime>& times, TimingClock clock) {
    std::printf("%-28s %10s\n", "pass", "ms");
    for (const PassTime& t : times) std::printf("%-28s %10.3f\n", t.name.c_str(), t.milliseconds);
    std::printf("%-28s %10.3f   (%s)\n", "total", totalMilliseconds(times), timingClockName(clock));
}

void printNotes(const PreparedFrame& frame) {
    for (const std::string& note : frame.notes) std::printf("%s\n", note.c_str());
    std::fflush(stdout);
}

void printSceneSummary(const PreparedFrame& frame) {
    const Bounds& b = frame.scene.bounds;
    const Camera& c = frame.settings.camera;
    std::printf("scene: %s, %zu triangles, %zu materials, %zu textures, bounds (%.2f %.2f %.2f)-(%.2f %.2f %.2f)\n",
                frame.scene.name.c_str(), frame.scene.triangleCount(), frame.scene.materials.size(),
                frame.scene.images.size(), b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z);
    std::printf("material paths compiled in: %s\n", describeMaterialFeatures(materialFeatures(frame.scene)).c_str());
    std::printf("camera: eye (%.2f %.2f %.2f) target (%.2f %.2f %.2f) fovy %.1f near %.4f far %.2f\n", c.eye.x, c.eye.y,
                c.eye.z, c.target.x, c.target.y, c.target.z, c.fovyDegrees, c.nearPlane, c.farPlane);
    std::printf("lights: %zu\n", frame.lights.size());
}

void printClusterStatistics(const ClusterStatistics& s) {
    std::printf("clusters: %u x %u x %u = %u, slicing %s over z %.3f..%.3f\n", s.tilesX, s.tilesY, s.slices, s.clusters,
                s.slicing.c_str(), s.zNear, s.zFar);
    if (s.zbin) {
        const ZBinStatistics& z = s.zbinStats;
        std::printf("zbin: %u bins (%d per slice), %u tiles, %u lights listed (culled to the view), %u words per tile\n",
                    z.bins, ML_ZBIN_PER_SLICE, z.tiles, z.listedLights, z.wordsPerTile);
        std::printf("zbin lights per pixel: walked %.2f (bin range), shaded %.2f (tile bit set)\n", z.meanWalkedPerPixel,
                    z.meanPassedPerPixel);
        std::printf("memory: zbin tile masks %.3f MiB, zbin total %.3f MiB\n", z.maskBytes / 1048576.0, z.totalBytes / 1048576.0);
        return;
    }
    std::printf("empty clusters: %.1f %%\n", 100.0 * s.emptyShare);
    std::printf("lights per cluster: mean %.2f (non-empty: %.2f), max %u\n", s.meanLightsPerCluster,
                s.meanLightsPerNonEmptyCluster, s.maxLightsPerCluster);
    std::printf("list entries: %llu\n", static_cast<unsigned long long>(s.listEntries));
    if (s.listsPerCluster > 1) {
        const std::uint64_t removed = s.normalConePairs - s.normalConePairsKept;
        std::printf("normal cones: lists per (cluster, normal bin), %u bins; of %llu light-cluster pairs in clusters with a visible "
                    "sample, %llu (%.1f %%) face away from every occupied bin and are removed; shares and means above are per list\n",
                    s.listsPerCluster, static_cast<unsigned long long>(s.normalConePairs), static_cast<unsigned long long>(removed),
                    s.normalConePairs ? 100.0 * removed / s.normalConePairs : 0.0);
    }
    std::printf("overflow: %u clusters over the cap, %llu light references dropped\n", s.overflowClusters,
                static_cast<unsigned long long>(s.droppedReferences));
    if (s.activeOnly) std::printf("active clusters: %u (%.1f %%)\n", s.activeClusters, 100.0 * s.activeClusters / std::max(1u, s.clusters));
    else std::printf("active clusters: not computed (use --active-only)\n");
    std::printf("memory: light lists %.2f MiB, grid %.2f MiB\n", s.listBytes / 1048576.0, s.gridBytes / 1048576.0);
}

void printShadingOptions(const FrameSettings& s, std::uint32_t materialFeatures) {
    const LightModel& m = s.lightModel;
    std::printf("BRDF: %s, specular %s\n", brdfName(m.brdf), s.specular ? "on" : "off (Lambert only)");
    std::printf("falloff: %s", falloffName(m.falloff));
    if (m.cutoff > 0.0f) std::printf(", cut-off E = %g", m.cutoff);
    std::printf(" (guard: distances below %g count as %g)\n", ML_LIGHT_MIN_DISTANCE, ML_LIGHT_MIN_DISTANCE);
    const MethodKind kind = s.method.kind;
    if (kind == MethodKind::Deferred || kind == MethodKind::Visibility) {
        const std::size_t perPixel = gbufferBytesPerPixel(s.method.gbuffer, materialFeatures);
        std::printf("G-buffer: %s, %zu B per pixel, %.2f MiB at %dx%d (depth: the frame's depth buffer)\n",
                    gbufferFormatName(s.method.gbuffer), perPixel,
                    static_cast<double>(perPixel) * s.width * s.height / 1048576.0, s.width, s.height);
    } else {
        std::printf("G-buffer: none (%s shades while rastering; --gbuffer is ignored)\n", methodName(kind).c_str());
    }
    if (kind == MethodKind::ForwardPlus)
        std::printf("depth pre-pass: %s\n", s.method.prepass ? "on (shade with EQUAL, each pixel once)"
                                                                : "off (one LESS pass; hidden fragments are shaded too)");
    if (kind == MethodKind::Deferred)
        std::printf("depth pre-pass: %s\n", s.method.prepass ? "on (G-buffer written with EQUAL, each pixel once)"
                                                                : "off (one LESS pass; hidden fragments write the G-buffer too)");
    // Two half-resolution RGBA32F images (renderer/passes/bloom_pass.h).
    const double bloomBytes = 2.0 * ((s.width + 1) / 2) * ((s.height + 1) / 2) * 16;
    if (s.bloom.enabled)
        std::printf("bloom: threshold %.3g, strength %.3g, %.2f MiB at half resolution\n", s.bloom.threshold,
                    s.bloom.strength, bloomBytes / 1048576.0);
    else std::printf("bloom: off\n");
}

void printShadowStructure(Shadows shadows, const ShadowRays* rays) {
    if (shadows == Shadows::Off) {
        std::printf("shadows: off\n");
        return;
    }
    if (rays == nullptr || rays->empty()) {
        std::printf("shadows: %s, nothing casts one (no triangle that is not BLEND): no ray is traced\n", shadowsName(shadows));
        return;
    }
    const ShadowStructureStats& s = rays->stats();
    std::printf("shadows: %s, %zu casting triangles (%zu alpha-tested), %zu nodes of %zu children, depth %zu, %.1f MiB, built in %.2f s\n",
                shadowsName(shadows), s.triangles, s.maskTriangles, s.nodes, s.width, s.depth, s.bytes / 1048576.0, s.buildSeconds);
}

void printCullAccuracy(const ClusterStatistics& s, const CullAccuracy& a) {
    std::printf("cull %s: %llu references, of which %llu (%.1f %%) reach no point of their cluster (exact sphere-frustum distance",
                s.cull.c_str(), static_cast<unsigned long long>(a.references), static_cast<unsigned long long>(a.falsePositives),
                a.references ? 100.0 * a.falsePositives / a.references : 0.0);
    if (a.clusterStride > 1) std::printf("; sampled: one cluster in %u, %u of %u", a.clusterStride, a.clustersExamined, s.clusters);
    std::printf(")\n");
    if (a.spotReferences > 0)
        std::printf("cull %s, spot lights: %llu references, of which %llu (%.1f %%) reach no point of their cluster with their cone "
                    "(exact sector-frustum test, GJK)\n",
                    s.cull.c_str(), static_cast<unsigned long long>(a.spotReferences),
                    static_cast<unsigned long long>(a.spotFalsePositives), 100.0 * a.spotFalsePositives / a.spotReferences);
}

void writeJsonFile(const std::string& path, const nlohmann::json& doc) {
    std::ofstream out(path);
    if (!out) throw std::runtime_error(path + ": cannot write");
    out << doc.dump(1) << "\n";
    if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace ml::app
