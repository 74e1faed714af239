// SIGINT (Ctrl-C), SIGTERM (what `timeout` and `kill` send) and SIGHUP (the
// terminal or ssh session closed) during `m3055 render` or `m3055 batch`.
// All three are handled alike, at once, whatever the
// command is doing (drawing, encoding, writing): every temporary file is
// removed (image/temporary_files.h), files already renamed into place are
// kept whole (a PNG and its PFM are renamed together, never one alone), one
// line says how far the command got, and the process ends by the same
// signal, so a shell sees 130, 143 or 129 and a script's loop stops.
#pragma once

#include <functional>
#include <string>
#include <thread>

#include <signal.h>

namespace m3055 {

class InterruptGuard {
public:
    // Blocks the three signals in this thread, and so in every thread started
    // after it (Mesa's and the encoders'): construct it before those. A thread
    // of its own waits for them. `line(signal)` gives the line to print, e.g.
    // "m3055: interrupted by SIGTERM: 3 of 40 scenes written, the rest not"; it
    // runs on that thread with the file-commit lock held, so what it reports
    // is exactly what is on disk (it must not take that lock itself).
    explicit InterruptGuard(std::function<std::string(int signal)> line);
    // Stops waiting and unblocks the signals (one arriving now ends the process).
    ~InterruptGuard();
    InterruptGuard(const InterruptGuard&) = delete;
    InterruptGuard& operator=(const InterruptGuard&) = delete;

private:
    void watch();
    [[noreturn]] void end_process(int signal);
    std::function<std::string(int)> line_;
    sigset_t previous_mask_;
    int signal_fd_ = -1, stop_fd_ = -1;
    std::thread watcher_;
};

// The last resort against a full disk under Mesa's shader cache: should a SIGBUS still happen (the
// disk under Mesa's shader cache filling up during the run, after
// disable_shader_cache_if_unusable() found room), the registered temporaries
// are removed and one line says what probably happened, naming the cache
// folder; exit status 1. Async-signal-safe: the line is made here, beforehand.
void report_bus_errors(const std::string& shader_cache_folder);

// "SIGINT", "SIGTERM", "SIGHUP", or "signal N".
std::string signal_name(int signal);

}  // namespace m3055
