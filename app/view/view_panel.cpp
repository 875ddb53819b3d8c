#include "app/view/view_panel.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "app/view/render_scale.h"
#include "renderer/clustering/cluster_grid.h"
#include "renderer/debug_view.h"
#include "renderer/lights/light_sum.h"

namespace ml::app {

namespace {

const ImVec4 kWarning{1.0f, 0.35f, 0.3f, 1.0f};
const ImVec4 kDim{0.65f, 0.65f, 0.65f, 1.0f};
constexpr float kItemWidth = 230.0f;   // sliders and combos
constexpr float kStatsWidth = 360.0f;  // the frame-time graph and the pass table
constexpr float kGraphHeight = 60.0f;

// A combo over names; returns true when the selection changed.
bool comboOf(const char* label, int& index, const std::vector<std::string>& names) {
    bool changed = false;
    if (ImGui::BeginCombo(label, names.at(static_cast<std::size_t>(index)).c_str())) {
        for (int i = 0; i < static_cast<int>(names.size()); ++i) {
            if (ImGui::Selectable(names[i].c_str(), i == index) && i != index) {
                index = i;
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

// A slider whose value is applied when it is let go: rebuilding lights or a method on every
// tick of a drag would compile shaders or regenerate a million lights per frame.
bool sliderOnRelease(const char* label, int& value, int min, int max, ImGuiSliderFlags flags = 0) {
    ImGui::SliderInt(label, &value, min, max, "%d", flags | ImGuiSliderFlags_AlwaysClamp);
    return ImGui::IsItemDeactivatedAfterEdit();
}

std::string mebibytes(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / 1048576.0);
    return text;
}

void methodSection(ViewSettings& s, PanelEdits& edits) {
    const auto& names = methodNames();
    const int current = static_cast<int>(std::find(names.begin(), names.end(), methodName(s.method.kind)) - names.begin());
    int kind = current;
    // One row while they fit in the panel's width, then the next.
    const float rowEnd = ImGui::GetCursorScreenPos().x + kItemWidth + 120.0f;
    for (int i = 0; i < static_cast<int>(names.size()); ++i) {
        char label[48];
        std::snprintf(label, sizeof label, "%s (%d)", names[i].c_str(), i + 1);
        if (i > 0) {
            const float width = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
            ImGui::SameLine();
            if (ImGui::GetCursorScreenPos().x + width > rowEnd) ImGui::NewLine();
        }
        if (ImGui::RadioButton(label, &kind, i)) edits.method = true;
    }
    if (kind != current) s.method.kind = parseMethod(names[static_cast<std::size_t>(kind)]);

    ImGui::BeginDisabled(s.method.kind != MethodKind::Deferred);
    int resolve = s.method.resolve == Resolve::Compute ? 0 : 1;
    if (comboOf("resolve", resolve, {"compute", "fragment"})) {
        s.method.resolve = resolve == 0 ? Resolve::Compute : Resolve::Fragment;
        edits.method = true;
    }
    ImGui::EndDisabled();

    ImGui::BeginDisabled(s.method.kind == MethodKind::Naive);
    int view = static_cast<int>(s.method.clustering.view);
    if (comboOf("debug view", view, debugViewNames())) {
        s.method.clustering.view = static_cast<DebugView>(view);
        edits.method = true;
    }
    ImGui::EndDisabled();
    if (s.method.kind == MethodKind::Naive) ImGui::TextColored(kDim, "naive: every pixel loops over every light");
}

// Where a light stops, on one row: the falloff (--cutoff) and beside it the radius (the seeds'
// smooth falloff) or the cut-off E (--light-cutoff: glTF's falloff, every radius where
// max(colour) / d^2 falls to E). A light set from --lights-file keeps its own falloff and radii.
void reachControls(ViewSettings& s, const ViewStatistics& stats, PanelEdits& edits) {
    static const std::vector<std::string> falloffs = {"radius", "cut-off", "stochastic", "none (naive)"};
    static const Falloff kinds[] = {Falloff::Smooth, Falloff::Gltf, Falloff::Stochastic, Falloff::Untruncated};
    int falloff = static_cast<int>(std::find(std::begin(kinds), std::end(kinds), s.falloff) - std::begin(kinds));
    const float combo = 0.45f * kItemWidth;
    ImGui::BeginDisabled(stats.lightsFromFile);
    ImGui::SetNextItemWidth(combo);
    if (comboOf("##falloff", falloff, falloffs)) {
        s.falloff = kinds[falloff];
        edits.lights = true;
    }
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("--cutoff: radius (the seeds' smooth falloff), cut-off (glTF's falloff, hard at each light's "
                          "E radius), stochastic (ranges drawn per frame past it: unbiased, noisy), none (every light "
                          "everywhere, naive only)");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::SetNextItemWidth(kItemWidth - combo - ImGui::GetStyle().ItemSpacing.x);
    if (s.falloff == Falloff::Smooth) {
        ImGui::SliderFloat("radius", &s.lightRadius, stats.sceneSize * 1e-3f, stats.sceneSize * 0.5f, "%.3f",
                           ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    } else {
        ImGui::BeginDisabled(s.falloff == Falloff::Untruncated || stats.lightsFromFile);
        ImGui::SliderFloat("E", &s.lightCutoff, 1e-4f, 1.0f, "%.4g", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
        ImGui::EndDisabled();
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) edits.lights = true;
}

void lightsSection(ViewSettings& s, const ViewStatistics& stats, PanelEdits& edits) {
    if (sliderOnRelease("lights", s.lightCount, 0, kMaxViewLights, ImGuiSliderFlags_Logarithmic)) edits.lights = true;
    reachControls(s, stats, edits);
    // Spot share and angle on one row: the panel must stay short enough to leave the lower
    // window to the scene.
    const float half = 0.5f * (kItemWidth - ImGui::GetStyle().ItemSpacing.x) - 28.0f;
    ImGui::SetNextItemWidth(half);
    ImGui::SliderFloat("spots", &s.spotShare, 0.0f, 1.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemDeactivatedAfterEdit()) edits.lights = true;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(half);
    ImGui::SliderFloat("angle", &s.spotAngle, 0.0f, 90.0f, s.spotAngle > 0.0f ? "%.0f deg" : "20-60", ImGuiSliderFlags_AlwaysClamp);
    if (ImGui::IsItemDeactivatedAfterEdit()) edits.lights = true;
    if (stats.sceneLights > 0) {
        if (ImGui::Checkbox("the file's lights", &s.sceneLights)) edits.lights = true;
        ImGui::SameLine();
        ImGui::TextColored(kDim, "(%zu)", stats.sceneLights);
    }
    if (stats.lightsFromFile) ImGui::TextColored(kDim, "lights from --lights-file until count or radius change");
    if (s.method.kind == MethodKind::Naive && s.lightCount > 65536)
        ImGui::TextColored(kWarning, "naive with %d lights: expect seconds per frame", s.lightCount);
    ImGui::Checkbox("animate", &s.animate);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(kItemWidth - ImGui::GetItemRectSize().x - ImGui::GetStyle().ItemSpacing.x);
    ImGui::SliderFloat("speed", &s.animationSpeed, 0.0f, 4.0f, "%.2fx");
    // One row: [x] auto [EV slider] and, while automatic, the exposure it measured.
    ImGui::Checkbox("auto", &s.autoExposure);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(kItemWidth - ImGui::GetItemRectSize().x - ImGui::GetStyle().ItemSpacing.x);
    ImGui::SliderFloat("##exposure", &s.exposureStops, -10.0f, 10.0f, s.autoExposure ? "%+.2f EV offset" : "%+.2f EV",
                       ImGuiSliderFlags_AlwaysClamp);
    ImGui::SameLine();
    if (s.autoExposure && stats.autoExposureStops) ImGui::TextColored(kDim, "exposure %+.1f", *stats.autoExposureStops);
    else ImGui::TextUnformatted("exposure");
}

// --msaa: greyed out, with the reason, for the methods that store one sample per pixel.
void msaaControl(ViewSettings& s, PanelEdits& edits) {
    const char* refusal = msaaRefusal(s.method.kind);
    static const std::vector<std::string> levels = {"1x (off)", "2x", "4x", "8x"};
    int level = s.method.msaa >= 8 ? 3 : s.method.msaa >= 4 ? 2 : s.method.msaa >= 2 ? 1 : 0;
    ImGui::BeginDisabled(refusal != nullptr);
    if (comboOf("MSAA", level, levels)) {
        s.method.msaa = 1 << level;
        edits.method = true;
    }
    ImGui::EndDisabled();
    if (refusal && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", refusal);
    if (refusal && s.method.msaa > 1) ImGui::TextColored(kDim, "MSAA off: %s", refusal);
}

// The shading options (issue 5): closed at start, so the panel keeps its height.
void shadingSection(ViewSettings& s, const ViewStatistics& stats, PanelEdits& edits) {
    // Scene submission (--draw): closed with the shading options, so the panel keeps its height.
    int draw = static_cast<int>(s.draw);
    if (comboOf("scene draws", draw, {drawSubmissionName(DrawSubmission::Direct), drawSubmissionName(DrawSubmission::Indirect)}))
        s.draw = static_cast<DrawSubmission>(draw);
    ImGui::Checkbox("back-face culling", &s.backfaceCulling);
    // Every method draws transparent surfaces: captured per pixel and shaded in compute (a
    // forward pass with --msaa).
    ImGui::BeginDisabled(stats.transparentRanges == 0);
    ImGui::Checkbox("transparency", &s.transparency);
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (stats.transparentRanges == 0) ImGui::TextColored(kDim, "(no BLEND material in this scene)");
    else ImGui::TextColored(kDim, "(%zu glass ranges, per-pixel depth order)", stats.transparentRanges);
    ImGui::BeginDisabled(s.method.kind != MethodKind::Deferred && s.method.kind != MethodKind::Visibility);
    int gbuffer = static_cast<int>(s.method.gbuffer);
    if (comboOf("G-buffer", gbuffer, gbufferFormatNames())) {
        s.method.gbuffer = static_cast<GBufferFormat>(gbuffer);
        edits.method = true;
    }
    ImGui::EndDisabled();
    ImGui::BeginDisabled(s.method.kind != MethodKind::ForwardPlus && s.method.kind != MethodKind::Deferred);
    if (ImGui::Checkbox("depth pre-pass (Forward+, deferred)", &s.method.prepass)) edits.method = true;
    ImGui::EndDisabled();
    msaaControl(s, edits);
    int brdf = s.brdf == Brdf::Ggx ? 0 : 1;
    if (comboOf("BRDF", brdf, {brdfName(Brdf::Ggx), brdfName(Brdf::BlinnPhong)})) {
        s.brdf = brdf == 0 ? Brdf::Ggx : Brdf::BlinnPhong;
        edits.brdf = true;
    }
    // Every method adds its lights this way, naive included: float over lists sorted by light
    // index, or 64-bit fixed point over unsorted lists (renderer/lights/light_sum.h).
    int lightSum = s.method.clustering.lightSum == LightSum::Fixed ? 1 : 0;
    if (comboOf("light sum", lightSum, {lightSumName(LightSum::Float), lightSumName(LightSum::Fixed)})) {
        s.method.clustering.lightSum = lightSum == 1 ? LightSum::Fixed : LightSum::Float;
        edits.method = true;
    }
    ImGui::SameLine();
    ImGui::TextColored(kDim, s.method.clustering.lightSum == LightSum::Fixed ? "(64-bit, lists unsorted)" : "(lists sorted)");
    ImGui::Checkbox("specular", &s.specular);
    ImGui::Checkbox("bloom", &s.bloom.enabled);
    ImGui::BeginDisabled(!s.bloom.enabled);
    ImGui::SliderFloat("bloom threshold", &s.bloom.threshold, 0.0f, 20.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    ImGui::SliderFloat("bloom strength", &s.bloom.strength, 0.0f, 4.0f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    ImGui::EndDisabled();
}

void gridSection(ViewSettings& s, PanelEdits& edits) {
    ClusteringSettings& c = s.method.clustering;
    ImGui::BeginDisabled(s.method.kind == MethodKind::Naive);
    int tilesX = static_cast<int>(c.grid.tilesX), slices = static_cast<int>(c.grid.slices);
    if (sliderOnRelease("tiles x", tilesX, 1, 256)) edits.method = true;
    if (sliderOnRelease("slices", slices, 1, 256)) edits.method = true;
    c.grid.tilesX = static_cast<std::uint32_t>(tilesX);
    c.grid.slices = static_cast<std::uint32_t>(slices);

    int slicing = static_cast<int>(c.grid.slicing);
    if (comboOf("slicing", slicing, {slicingName(Slicing::Linear), slicingName(Slicing::Log), slicingName(Slicing::Fitted)})) {
        c.grid.slicing = static_cast<Slicing>(slicing);
        edits.method = true;
    }
    static const std::vector<std::string> groups{"32", "64", "128", "256", "512", "1024"};
    int group = 0;
    while (group + 1 < static_cast<int>(groups.size()) && std::stoul(groups[group]) < c.grid.workgroup) ++group;
    if (comboOf("workgroup", group, groups)) {
        c.grid.workgroup = static_cast<std::uint32_t>(std::stoul(groups[group]));
        edits.method = true;
    }
    int assign = static_cast<int>(c.assign);
    if (comboOf("assignment", assign, {assignModeName(AssignMode::Exact), assignModeName(AssignMode::Capped),
                                       assignModeName(AssignMode::PerCluster), assignModeName(AssignMode::ZBin)})) {
        c.assign = static_cast<AssignMode>(assign);
        edits.method = true;
    }
    if (c.assign == AssignMode::Capped) {
        int cap = static_cast<int>(c.maxPerCluster);
        if (sliderOnRelease("max per cluster", cap, 1, 8192, ImGuiSliderFlags_Logarithmic)) edits.method = true;
        c.maxPerCluster = static_cast<std::uint32_t>(cap);
    }
    if (ImGui::Checkbox("active clusters only", &c.activeOnly)) edits.method = true;
    // Normal bins need a normal before shading (deferred, visibility) and uncapped lists.
    const bool gbufferLit = s.method.kind == MethodKind::Deferred || s.method.kind == MethodKind::Visibility;
    ImGui::SameLine();
    ImGui::BeginDisabled(!gbufferLit || c.assign == AssignMode::Capped);
    if (ImGui::Checkbox("normal cones", &c.normalCones)) edits.method = true;
    ImGui::EndDisabled();
    int cull = static_cast<int>(c.cull);
    if (comboOf("cull test", cull, {cullModeName(CullMode::Aabb), cullModeName(CullMode::Sphere), cullModeName(CullMode::Cone)})) {
        c.cull = static_cast<CullMode>(cull);
        edits.method = true;
    }
    if (c.normalCones && !gbufferLit) ImGui::TextColored(kDim, "normal cones: off for %s (no normal before shading)", methodName(s.method.kind).c_str());
    ImGui::EndDisabled();
}

void cameraSection(ViewSettings& s, const ViewStatistics& stats, PanelEdits& edits) {
    int mode = static_cast<int>(s.cameraMode);
    if (ImGui::RadioButton("fly", &mode, 0)) edits.cameraMode = true;
    ImGui::SameLine();
    if (ImGui::RadioButton("orbit (C)", &mode, 1)) edits.cameraMode = true;
    s.cameraMode = static_cast<CameraMode>(mode);
    ImGui::SameLine();
    if (ImGui::Button("reset (R)")) edits.resetCamera = true;
    ImGui::SameLine();
    if (ImGui::Button("frame (F)")) edits.frameScene = true;
    // On the same row, as the panel must leave the lower window to the scene.
    if (s.cameraMode == CameraMode::Fly) {
        ImGui::SameLine();
        ImGui::TextColored(kDim, "%.2f u/s (scroll)", stats.flySpeed);
    }
    if (!stats.sceneCameras.empty()) {
        const std::string current = s.sceneCamera < 0 ? "free camera" : stats.sceneCameras[static_cast<std::size_t>(s.sceneCamera)];
        if (ImGui::BeginCombo("view from", current.c_str())) {
            for (int i = -1; i < static_cast<int>(stats.sceneCameras.size()); ++i) {
                const char* label = i < 0 ? "free camera" : stats.sceneCameras[static_cast<std::size_t>(i)].c_str();
                if (ImGui::Selectable(label, i == s.sceneCamera)) {
                    s.sceneCamera = i;
                    edits.sceneCamera = true;
                }
            }
            ImGui::EndCombo();
        }
    }
    if (ImGui::Checkbox("vsync", &s.vsync)) edits.vsync = true;
    ImGui::SameLine();
    if (ImGui::Button("screenshot (F12)")) edits.screenshot = true;
    // On the same line: the panel must stay short enough to leave the lower window to the scene.
    ImGui::SameLine();
    ImGui::SetNextItemWidth(60.0f);
    ImGui::SliderFloat("render scale", &s.renderScale, kMinRenderScale, 1.0f, "%.2f");
    if (ImGui::IsItemDeactivatedAfterEdit()) edits.renderScale = true;
    if (!stats.renderScaleNote.empty()) {
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + kItemWidth + 80.0f);
        ImGui::TextColored(kDim, "%s", stats.renderScaleNote.c_str());
        ImGui::PopTextWrapPos();
    }
}

void statisticsSection(const ViewStatistics& st) {
    const double fps = st.frameMilliseconds > 0.0 ? 1000.0 / st.frameMilliseconds : 0.0;
    ImGui::Text("frame %.2f ms (%.1f fps), %dx%d", st.frameMilliseconds, fps, st.width, st.height);
    if (!st.frameGraph.empty()) {
        const float top = std::max(1.0f, *std::max_element(st.frameGraph.begin(), st.frameGraph.end()) * 1.1f);
        char overlay[32];
        std::snprintf(overlay, sizeof overlay, "0..%.1f ms", top);
        ImGui::PlotLines("##frames", st.frameGraph.data(), static_cast<int>(st.frameGraph.size()), 0, overlay, 0.0f, top,
                         ImVec2(kStatsWidth, kGraphHeight));
    } else {
        // Keep the space: the window sizes itself a frame late, and must not grow under a screenshot.
        ImGui::Dummy(ImVec2(kStatsWidth, kGraphHeight));
    }

    ImGui::TextColored(kDim, "passes, mean of recent frames");
    ImGui::TextColored(kDim, "(%s)", timingClockName(st.clock));
    if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp, ImVec2(kStatsWidth, 0.0f))) {
        for (const PassTime& p : st.passes) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(p.name.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%8.3f ms", p.milliseconds);
        }
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted("total");
        ImGui::TableNextColumn();
        ImGui::Text("%8.3f ms", totalMilliseconds(st.passes));
        ImGui::EndTable();
    }
    if (!st.shadows.empty()) ImGui::TextUnformatted(st.shadows.c_str());

    if (st.clusters) {
        const ClusterStatistics& c = *st.clusters;
        ImGui::Text("clusters %u x %u x %u = %u (%s)", c.tilesX, c.tilesY, c.slices, c.clusters, c.slicing.c_str());
        ImGui::Text("sliced depth %.3f .. %.3f", c.zNear, c.zFar);
        if (c.zbin) {
            const ZBinStatistics& z = c.zbinStats;
            ImGui::Text("zbin: %u bins, %u tiles x %u words, %u lights listed", z.bins, z.tiles, z.wordsPerTile, z.listedLights);
            ImGui::Text("lights per pixel: walked %.1f, shaded %.1f", z.meanWalkedPerPixel, z.meanPassedPerPixel);
            ImGui::Text("zbin memory: masks %s, total %s", mebibytes(z.maskBytes).c_str(), mebibytes(z.totalBytes).c_str());
        } else {
        ImGui::Text("empty clusters %.1f %%", 100.0 * c.emptyShare);
        ImGui::Text("lights per cluster: mean %.1f (non-empty %.1f), max %u", c.meanLightsPerCluster,
                    c.meanLightsPerNonEmptyCluster, c.maxLightsPerCluster);
        ImGui::Text("list entries %llu (cull %s)", static_cast<unsigned long long>(c.listEntries), c.cull.c_str());
        if (c.listsPerCluster > 1 && c.normalConePairs > 0)
            ImGui::Text("normal cones: %.1f %% of light-cluster pairs removed", 100.0 * double(c.normalConePairs - c.normalConePairsKept) / double(c.normalConePairs));
        if (c.overflowClusters > 0)
            ImGui::TextColored(kWarning, "overflow: %u clusters over the cap,\n%llu light references dropped",
                               c.overflowClusters, static_cast<unsigned long long>(c.droppedReferences));
        else ImGui::Text("overflow: none");
        if (c.activeOnly) ImGui::Text("active clusters %u (%.1f %%)", c.activeClusters, 100.0 * c.activeClusters / std::max(1u, c.clusters));
        else ImGui::TextColored(kDim, "active clusters: tick \"active clusters only\"");
        ImGui::Text("cluster memory: lists %s, grid %s", mebibytes(c.listBytes).c_str(), mebibytes(c.gridBytes).c_str());
        }
    } else {
        ImGui::TextColored(kDim, "no clusters: naive shades %zu lights per pixel", st.lights);
    }
    if (st.gbuffer) {
        const std::size_t perPixel = st.gbufferPixelBytes;
        ImGui::Text("G-buffer %s: %zu B/pixel, %s", gbufferFormatName(*st.gbuffer), perPixel,
                    mebibytes(perPixel * static_cast<std::size_t>(st.width) * st.height).c_str());
    } else {
        ImGui::TextColored(kDim, "G-buffer: none (this method shades while rastering)");
    }
    ImGui::Text("renderer memory %s", mebibytes(st.rendererBytes).c_str());
    if (st.gpuUsedBytes) ImGui::Text("GPU memory in use %s", mebibytes(*st.gpuUsedBytes).c_str());
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + kStatsWidth);
    ImGui::TextWrapped("%s", st.glRenderer.c_str());
    ImGui::PopTextWrapPos();
    ImGui::TextColored(kDim, "%s", st.glVersion.c_str());
    if (st.glErrors > 0) ImGui::TextColored(kWarning, "%d GL error(s)", st.glErrors);
}

// Another file without restarting (dropping one on the window does the same).
void openFileField(ViewSettings& s, PanelEdits& edits) {
    ImGui::SetNextItemWidth(kItemWidth + 60.0f);
    const bool entered = ImGui::InputTextWithHint("##open", "path/to/file.gltf, or drop one on the window", s.openPath.data(),
                                                  s.openPath.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("open") || entered) && s.openPath[0] != '\0') edits.openFile = true;
}

void keysSection() {
    ImGui::TextUnformatted(
        "fly:   WASD move, Q/E down/up, Shift faster,\n"
        "       right mouse button + drag looks, wheel: speed\n"
        "orbit: drag orbits, wheel zooms\n"
        "C fly/orbit, R reset view, F frame the scene,\n"
        "1/2/3/... method, drop a .gltf/.glb to open it,\n"
        "F1 or H hide panel, F12 screenshot, Esc quit");
}

}  // namespace

MethodSettings effectiveMethod(const MethodSettings& chosen) {
    MethodSettings m = chosen;
    if (m.kind == MethodKind::Naive) m.clustering.view = DebugView::Shaded;
    if (msaaRefusal(m.kind)) m.msaa = 1;  // kept in the panel for the methods that take it
    if (m.clustering.view == DebugView::Overdraw) m.msaa = 1;  // the view counts per pixel (kOverdrawRefusesMsaa)
    if ((m.kind != MethodKind::Deferred && m.kind != MethodKind::Visibility) || m.clustering.assign == AssignMode::Capped)
        m.clustering.normalCones = false;
    return m;
}

PanelEdits drawViewPanel(ViewSettings& settings, const ViewStatistics& stats) {
    PanelEdits edits;
    // Controls at the top left, statistics at the top right; both size themselves to their
    // contents (fixed item widths, so sizing does not feed back into itself).
    const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize;
    ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    // Rows 1 px closer than ImGui's default, so the panel with every section's controls still
    // ends above 580 px at the 640 px default window height.
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(ImGui::GetStyle().ItemSpacing.x, ImGui::GetStyle().ItemSpacing.y - 1.0f));
    if (ImGui::Begin("manylights", nullptr, flags)) {
        ImGui::PushItemWidth(kItemWidth);
        if (!stats.error.empty()) {
            ImGui::PushTextWrapPos(kItemWidth + 120.0f);
            ImGui::TextColored(kWarning, "%s", stats.error.c_str());
            ImGui::PopTextWrapPos();
        }
        if (ImGui::CollapsingHeader("Method", ImGuiTreeNodeFlags_DefaultOpen)) methodSection(settings, edits);
        if (ImGui::CollapsingHeader("Lights", ImGuiTreeNodeFlags_DefaultOpen)) lightsSection(settings, stats, edits);
        if (ImGui::CollapsingHeader("Cluster grid", ImGuiTreeNodeFlags_DefaultOpen)) gridSection(settings, edits);
        if (ImGui::CollapsingHeader("Shading")) shadingSection(settings, stats, edits);
        if (ImGui::CollapsingHeader("Camera and window", ImGuiTreeNodeFlags_DefaultOpen)) cameraSection(settings, stats, edits);
        // Only a file with KHR_materials_variants has the section.
        if (!stats.materialVariants.empty() && ImGui::CollapsingHeader("Material variants", ImGuiTreeNodeFlags_DefaultOpen) &&
            comboOf("variant", settings.materialVariant, stats.materialVariants))
            edits.materialVariant = true;
        if (ImGui::CollapsingHeader("Open a file, keys")) {
            openFileField(settings, edits);
            keysSection();
        }
        ImGui::PopItemWidth();
    }
    ImGui::End();
    ImGui::PopStyleVar();

    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - 10.0f, 10.0f), ImGuiCond_FirstUseEver, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    if (ImGui::Begin("statistics", nullptr, flags)) statisticsSection(stats);
    ImGui::End();
    return edits;
}

}  // namespace ml::app
