// A duration as a person reads it in a progress line ("42s", "3m07s", "1h05m"), shared by
// bench's progress bar and render's sequence progress.
#pragma once

#include <string>

namespace ml::app {

// "1m05s", "42s", "1h02m".
std::string formatDuration(double seconds);

}  // namespace ml::app
