// What the binary was built from, for benchmark records. Defined in a file generated at build
// time by cmake/build_info.cmake (`git rev-parse HEAD`, or "unknown" outside a checkout).
#pragma once

namespace ml::app {

const char* buildCommit();
bool buildHasLocalChanges();  // tracked files differed from the commit when it was built
const char* buildType();      // CMAKE_BUILD_TYPE
const char* buildCompiler();  // compiler id and version

}  // namespace ml::app
