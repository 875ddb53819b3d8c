// The machine and build a measurement was taken on, for the records `bench` writes: numbers
// from an H100 and from llvmpipe must never be mistaken for one another.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "renderer/context/gl_context.h"

namespace ml::app {

// The CPU's model name from /proc/cpuinfo ("unknown" where there is none).
std::string cpuModel();

// GL_RENDERER, GL_VERSION, GL_VENDOR, the context platform, the CPU, threads, memory, the OS.
nlohmann::ordered_json describeMachine(const GlInfo& gl, const std::string& platform);

// The commit (from the build), whether it had local changes, the build type and compiler.
nlohmann::ordered_json describeBuild();

}  // namespace ml::app
