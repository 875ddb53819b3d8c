// KHR_debug messages: errors are counted (tests fail on any) and printed once each.
#pragma once

#include <string>

namespace ml::gl {

enum class DebugVerbosity { ErrorsOnly, All };

// Installs the message callback on the current context (synchronous, so a message's stack is the culprit's).
void enableDebugOutput(DebugVerbosity verbosity = DebugVerbosity::ErrorsOnly);

int debugErrorCount();
std::string lastDebugError();
void resetDebugErrors();

// GL errors from glGetError since the last call, as text ("" when none).
std::string drainGlErrors();

}  // namespace ml::gl
