#include "app/bench/bench_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace ml::app {

namespace {

// Before the pass columns: what the point is and how long a frame took.
const std::vector<std::string> kLeadingColumns = {
    "experiment", "point", "scene", "material_variant", "method", "lights", "spot_share", "radius", "radius_rule", "seed", "intensity", "drift_speed", "specular", "brdf", "shadows", "shadow_bvh_width", "shadow_rays_per_pixel", "shadow_reuse", "shadow_denoise", "light_sum", "light_cutoff", "cutoff", "accumulate", "bloom",
    "width", "height", "camera", "near", "far", "tiles_x", "tiles_y", "slices", "slicing", "assign",
    "max_per_cluster", "active_only", "cull", "normal_cones", "gbuffer", "resolve", "vis_raster", "prepass", "msaa", "draw", "draw_calls", "backface_culling", "transparency", "triangle_order", "workgroup", "frame_index", "warmup_frames",
    "timed_frames", "clock", "sm_clock_mhz", "sm_clock_mhz_min", "frame_ms", "frame_ms_p10", "frame_ms_p90", "wall_ms",
};
// After them: accuracy, cluster statistics, memory, the machine and what went wrong.
const std::vector<std::string> kTrailingColumns = {
    "max_abs_err", "rmse", "psnr_db", "bad_pixel_share", "ldr_max_abs_err", "ldr_psnr_db", "ldr_bad_pixel_share",
    "reference", "aa_rmse", "aa_psnr_db", "aa_reference", "physical_max_abs_err", "physical_rmse", "physical_psnr_db",
    "physical_ldr_max_abs_err", "physical_ldr_psnr_db", "physical_ldr_bad_pixel_share", "shadow_max_abs_err", "shadow_rmse", "shadow_psnr_db",
    "shadow_ldr_max_abs_err", "shadow_ldr_bad_pixel_share", "shadow_flicker_psnr_db", "shadow_flicker_ldr_share", "clusters", "empty_share", "mean_lights_per_cluster", "mean_lights_per_nonempty_cluster",
    "max_lights_per_cluster", "list_entries", "false_positive_share", "normal_cone_pairs_removed", "overflow_clusters", "dropped_lights", "active_clusters",
    "list_bytes", "grid_bytes", "zbin_mask_bytes", "zbin_lights_walked", "zbin_lights_shaded", "shadow_rays", "shadow_grays_per_s", "gbuffer_bytes",
    "target_bytes", "light_bytes", "renderer", "note",
};

bool isFixed(const std::string& column) {
    return std::find(kLeadingColumns.begin(), kLeadingColumns.end(), column) != kLeadingColumns.end() ||
           std::find(kTrailingColumns.begin(), kTrailingColumns.end(), column) != kTrailingColumns.end();
}

bool isPassColumn(const std::string& column) {
    return column.rfind("pass_", 0) == 0 &&
           (column.ends_with("_ms") || column.ends_with("_ms_p10") || column.ends_with("_ms_p90"));
}

std::string csvCell(const nlohmann::ordered_json& v) {
    std::string text;
    if (v.is_null()) return text;
    if (v.is_string()) text = v.get<std::string>();
    else if (v.is_boolean()) text = v.get<bool>() ? "true" : "false";
    else if (v.is_number_integer()) text = v.dump();
    else if (v.is_number_float()) {
        const double d = v.get<double>();
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.6g", d);
        text = buf;
    } else text = v.dump();
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

}  // namespace

void BenchTable::add(BenchRow row) {
    for (const auto& [key, value] : row.items()) {
        if (isFixed(key)) continue;
        if (!isPassColumn(key)) throw std::logic_error("bench: unknown column '" + key + "'");
        // Keep a pass's _ms, _p10 and _p90 together, in the order the passes ran.
        const std::string base = key.substr(0, key.rfind("_ms") + 3);
        if (std::find(passColumns_.begin(), passColumns_.end(), base) == passColumns_.end()) passColumns_.push_back(base);
    }
    rows_.push_back(std::move(row));
}

std::vector<std::string> BenchTable::columns() const {
    std::vector<std::string> out = kLeadingColumns;
    for (const std::string& base : passColumns_) {
        out.push_back(base);
        out.push_back(base + "_p10");
        out.push_back(base + "_p90");
    }
    out.insert(out.end(), kTrailingColumns.begin(), kTrailingColumns.end());
    return out;
}

void BenchTable::writeCsv(const std::string& path) const {
    const std::vector<std::string> cols = columns();
    std::string text;
    for (std::size_t i = 0; i < cols.size(); ++i) text += (i ? "," : "") + cols[i];
    text += "\n";
    for (const BenchRow& row : rows_) {
        for (std::size_t i = 0; i < cols.size(); ++i) {
            if (i) text += ",";
            if (row.contains(cols[i])) text += csvCell(row.at(cols[i]));
        }
        text += "\n";
    }
    writeFileAtomically(path, text);
}

nlohmann::ordered_json BenchTable::rowsJson() const {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    const std::vector<std::string> cols = columns();
    for (const BenchRow& row : rows_) {
        nlohmann::ordered_json r = nlohmann::ordered_json::object();
        for (const std::string& c : cols) r[c] = row.contains(c) ? row.at(c) : nullptr;
        out.push_back(std::move(r));
    }
    return out;
}

}  // namespace ml::app
