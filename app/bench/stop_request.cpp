#include "app/bench/stop_request.h"

#include <csignal>
#include <unistd.h>

namespace ml::app {

namespace {

volatile std::sig_atomic_t gStop = 0;
struct sigaction gPrevious {};

void onInterrupt(int) {
    gStop = 1;
    // Async-signal-safe: write(2), and SA_RESETHAND already put the default action back for a
    // second Ctrl-C.
    const char message[] = "\nmanylights bench: stopping after this point (Ctrl-C again to quit now)\n";
    [[maybe_unused]] const auto n = write(STDERR_FILENO, message, sizeof message - 1);
}

}  // namespace

StopRequest::StopRequest() {
    gStop = 0;
    struct sigaction action {};
    action.sa_handler = onInterrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &action, &gPrevious);
}

StopRequest::~StopRequest() { sigaction(SIGINT, &gPrevious, nullptr); }

bool StopRequest::requested() const { return gStop != 0; }

}  // namespace ml::app
