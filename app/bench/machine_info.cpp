#include "app/bench/machine_info.h"

#include <sys/utsname.h>

#include <fstream>
#include <thread>

#include "app/build_info.h"

namespace ml::app {

namespace {

// The value of the first "key : value" line of a /proc file whose key is `key`.
std::string procField(const char* path, const std::string& key) {
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        const auto colon = line.find(':');
        if (colon == std::string::npos) continue;
        std::string k = line.substr(0, colon);
        k.erase(k.find_last_not_of(" \t") + 1);
        if (k != key) continue;
        std::string v = line.substr(colon + 1);
        v.erase(0, v.find_first_not_of(" \t"));
        return v;
    }
    return {};
}

}  // namespace

std::string cpuModel() {
    const std::string model = procField("/proc/cpuinfo", "model name");
    return model.empty() ? "unknown" : model;
}

nlohmann::ordered_json describeMachine(const GlInfo& gl, const std::string& platform) {
    nlohmann::ordered_json m;
    m["gl_renderer"] = gl.renderer;
    m["gl_version"] = gl.version;
    m["gl_vendor"] = gl.vendor;
    m["gl_platform"] = platform;
    m["software_renderer"] = gl.software;
    m["cpu"] = cpuModel();
    m["cpu_threads"] = std::thread::hardware_concurrency();
    m["memory"] = procField("/proc/meminfo", "MemTotal");
    utsname u{};
    m["os"] = uname(&u) == 0 ? std::string(u.sysname) + " " + u.release + " " + u.machine : "unknown";
    return m;
}

nlohmann::ordered_json describeBuild() {
    nlohmann::ordered_json b;
    b["commit"] = buildCommit();
    b["local_changes"] = buildHasLocalChanges();
    b["build_type"] = buildType();
    b["compiler"] = buildCompiler();
    return b;
}

}  // namespace ml::app
