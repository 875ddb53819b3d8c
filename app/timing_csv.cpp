#include "app/timing_csv.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace ml::app {

std::string passColumn(const std::string& passName) {
    std::string s = "pass_";
    for (char c : passName) {
        if (c == '+') s += "_plus_";  // "forward+.shade" -> "forward_plus_shade"
        else s += (c == '.' || c == '-' || c == ' ') ? '_' : c;
    }
    std::string out;  // runs of '_' collapse to one
    for (char c : s)
        if (!(c == '_' && !out.empty() && out.back() == '_')) out += c;
    return out + "_ms";
}

const char* clockColumnValue(TimingClock clock) {
    return clock == TimingClock::GpuQueries ? "gpu-timer-queries" : "wall-clock-after-glfinish";
}

void writeFileAtomically(const std::string& path, const std::string& text) {
    const std::string temporary = path + ".partial";
    {
        std::ofstream out(temporary, std::ios::binary);
        if (!out) throw std::runtime_error(path + ": cannot write");
        out << text;
        if (!out.flush()) throw std::runtime_error(path + ": write failed");
    }
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) throw std::runtime_error(path + ": cannot rename " + temporary + ": " + ec.message());
}

}  // namespace ml::app
