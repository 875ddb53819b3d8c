#include <stdexcept>
#include <string>

#include "renderer/methods/clustered_deferred.h"
#include "renderer/methods/forward_plus.h"
#include "renderer/methods/naive_forward.h"
#include "renderer/methods/visibility_buffer.h"
#include "renderer/methods/shading_method.h"

namespace ml {

namespace {
struct MethodEntry {
    MethodKind kind;
    const char* name;
};
constexpr MethodEntry kMethods[] = {
    {MethodKind::Naive, "naive"},
    {MethodKind::ForwardPlus, "forward-plus"},
    {MethodKind::Deferred, "deferred"},
    {MethodKind::Visibility, "visibility"},
};
}  // namespace

const std::vector<std::string>& methodNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const MethodEntry& m : kMethods) out.emplace_back(m.name);
        return out;
    }();
    return names;
}

MethodKind parseMethod(const std::string& text) {
    for (const MethodEntry& m : kMethods)
        if (text == m.name) return m.kind;
    std::string list;
    for (const std::string& n : methodNames()) list += (list.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown method '" + text + "' (expected one of: " + list + ")");
}

std::string methodName(MethodKind kind) {
    for (const MethodEntry& m : kMethods)
        if (kind == m.kind) return m.name;
    return "?";
}

const char* msaaRefusal(MethodKind kind) {
    switch (kind) {
    case MethodKind::Deferred: return "deferred stores one sample per pixel in its G-buffer (MSAA needs naive or forward-plus)";
    case MethodKind::Visibility:
        return "visibility stores one triangle id per pixel and lights one sample per pixel (MSAA needs naive or forward-plus)";
    default: return nullptr;
    }
}

int validMsaa(long long samples) {
    if (samples != 1 && samples != 2 && samples != 4 && samples != 8)
        throw std::invalid_argument("--msaa " + std::to_string(samples) + ": must be 1, 2, 4 or 8");
    return static_cast<int>(samples);
}

std::unique_ptr<ShadingMethod> createMethod(const MethodSettings& settings, std::uint32_t materialFeatures) {
    checkLightSumSupported(settings.clustering.lightSum);
    if (const char* refusal = msaaRefusal(settings.kind); refusal && settings.msaa > 1)
        throw std::invalid_argument("--msaa " + std::to_string(settings.msaa) + ": " + refusal);
    const TransparencySettings transparency{settings.msaa, settings.transparentCaptureBudget, settings.glassLayerGroups};
    switch (settings.kind) {
    case MethodKind::Naive: return std::make_unique<NaiveForward>(materialFeatures, settings.clustering, transparency);
    case MethodKind::ForwardPlus: {
        // Forward+ shades before any normal is known: no normal bins (the flag is refused by
        // `render` and greyed out in `view`; here it is ignored).
        ClusteringSettings clustering = settings.clustering;
        clustering.normalCones = false;
        clustering.depthSamples = static_cast<std::uint32_t>(settings.msaa);
        return std::make_unique<ForwardPlus>(clustering, settings.prepass, materialFeatures, transparency);
    }
    case MethodKind::Deferred:
        return std::make_unique<ClusteredDeferred>(settings.clustering, settings.resolve, settings.gbuffer, settings.prepass,
                                                   materialFeatures, transparency);
    case MethodKind::Visibility:
        return std::make_unique<VisibilityBuffer>(settings.clustering, settings.gbuffer, materialFeatures, transparency,
                                                  ComputeRaster::resolve(settings.visibilityRaster));
    }
    throw std::invalid_argument("unhandled method");
}

Resolve parseResolve(const std::string& text) {
    if (text == "fragment") return Resolve::Fragment;
    if (text == "compute") return Resolve::Compute;
    throw std::invalid_argument("--resolve '" + text + "': expected fragment or compute");
}

const char* resolveName(Resolve resolve) { return resolve == Resolve::Fragment ? "fragment" : "compute"; }

}  // namespace ml
