#include "app/crash_report.h"

#include <dlfcn.h>
#include <execinfo.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <initializer_list>

namespace ml::app {

namespace {

void writeText(const char* text) { (void)!write(STDERR_FILENO, text, std::strlen(text)); }

// Not async-signal-safe in every part (dladdr, snprintf), which is acceptable for a process
// that is about to end: the report is a best effort, then the default action runs.
void report(int signal) {
    void* frames[48];
    const int n = backtrace(frames, 48);
    char line[256];
    std::snprintf(line, sizeof line, "manylights: fatal signal %d (%s); stack:", signal, strsignal(signal));
    writeText(line);
    for (int i = 0; i < n; ++i) {
        Dl_info info{};
        if (dladdr(frames[i], &info) && info.dli_fname) {
            const char* name = std::strrchr(info.dli_fname, '/');
            std::snprintf(line, sizeof line, " %s+0x%lx", name ? name + 1 : info.dli_fname,
                          static_cast<unsigned long>(static_cast<char*>(frames[i]) - static_cast<char*>(info.dli_fbase)));
        } else {
            std::snprintf(line, sizeof line, " %p", frames[i]);
        }
        writeText(line);
    }
    writeText("\n");
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

}  // namespace

void installCrashReport() {
#if defined(__SANITIZE_ADDRESS__)
    return;  // the sanitizer's own report is the better one
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(undefined_behavior_sanitizer)
    return;
#endif
#endif
    for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(s, report);
}

}  // namespace ml::app
