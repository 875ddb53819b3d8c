// Ctrl-C during a long sweep: the first SIGINT asks the sweep to stop after the point it is
// measuring (so what was measured is written); a second one ends the process at once.
#pragma once

namespace ml::app {

class StopRequest {
public:
    StopRequest();   // installs the SIGINT handler
    ~StopRequest();  // restores the previous one
    StopRequest(const StopRequest&) = delete;
    StopRequest& operator=(const StopRequest&) = delete;

    bool requested() const;
};

}  // namespace ml::app
