// Ending a command that has finished its work without tearing down what it
// built: the GL context, llvmpipe's threads, LLVM and the heap are the
// operating system's to free at exit, which it does faster than their
// destructors do (docs/bench/capture.md measures the difference).
#pragma once

namespace m3055 {

// Flushes stdout and stderr (C++ and C streams) and ends the process with
// `status`, running no destructor and no atexit handler. Under a sanitizer it
// returns instead, so the caller's normal exit runs the sanitizer's checks.
void exit_now(int status);

}  // namespace m3055
