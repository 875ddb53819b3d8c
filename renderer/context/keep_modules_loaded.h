// Keeps the GL driver's shared objects mapped until exit in sanitizer builds.
//
// Why: EGL and OSMesa dlclose their driver (Mesa's llvmpipe, LLVM's JIT) when a display is
// terminated. LeakSanitizer runs at exit, after that, and sees the driver's process-lifetime
// allocations as leaks from "<unknown module>", which no suppression can name. Marking every
// module loaded at context creation RTLD_NODELETE keeps them mapped, so the reports name
// swrast_dri.so, libLLVM and friends and tests/sanitizers/lsan.supp can suppress them, while
// leaks in our own code still fail. A no-op in normal builds.
#pragma once

namespace ml {

void keepLoadedModulesUntilExit();

}  // namespace ml
