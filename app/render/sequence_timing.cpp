#include "app/render/sequence_timing.h"

#include <algorithm>
#include <cstdio>

#include "app/timing_csv.h"

namespace ml::app {

namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

}  // namespace

void SequenceTiming::add(std::uint32_t frame, const Camera& camera, const std::vector<PassTime>& passes, double wallMs) {
    for (const PassTime& p : passes)
        if (std::find(passNames_.begin(), passNames_.end(), p.name) == passNames_.end()) passNames_.push_back(p.name);
    rows_.push_back(Row{frame, camera, passes, wallMs});
}

void SequenceTiming::writeCsv(const std::string& path) const {
    std::string text = "frame_index,eye_x,eye_y,eye_z,target_x,target_y,target_z,fovy,clock,frame_ms,wall_ms";
    for (const std::string& name : passNames_) text += "," + passColumn(name);
    text += "\n";
    for (const Row& r : rows_) {
        const Camera& c = r.camera;
        text += std::to_string(r.frame);
        for (float v : {c.eye.x, c.eye.y, c.eye.z, c.target.x, c.target.y, c.target.z, c.fovyDegrees}) text += "," + number(v);
        text += std::string(",") + clockColumnValue(clock_) + "," + number(totalMilliseconds(r.passes)) + "," + number(r.wallMs);
        for (const std::string& name : passNames_) {
            const auto it = std::find_if(r.passes.begin(), r.passes.end(), [&](const PassTime& p) { return p.name == name; });
            text += "," + (it == r.passes.end() ? std::string() : number(it->milliseconds));  // a pass this frame skipped
        }
        text += "\n";
    }
    writeFileAtomically(path, text);
}

std::vector<PassTime> SequenceTiming::meanPasses() const {
    std::vector<PassTime> means;
    for (const std::string& name : passNames_) {
        double sum = 0.0;
        for (const Row& r : rows_)
            for (const PassTime& p : r.passes)
                if (p.name == name) sum += p.milliseconds;
        means.push_back(PassTime{name, rows_.empty() ? 0.0 : sum / static_cast<double>(rows_.size())});
    }
    return means;
}

}  // namespace ml::app
