// On a fatal signal (a crash: a bug, or a GL driver fault), one line on stderr that names the
// signal and the call stack as object+offset pairs, which `addr2line -e <unstripped binary>`
// turns into source lines even where the binary that crashed was stripped (the GPU runs).
#pragma once

namespace ml::app {

void installCrashReport();

}  // namespace ml::app
