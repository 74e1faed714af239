// A line on a terminal when a step outlasts a few seconds, so that a render
// llvmpipe needs minutes for (a 512 x 320 scene under a shadowed sky; a new
// scene's shaders, compiled once, then in Mesa's cache) does not look like a
// hang; and when it ends, how long it took (or that it stopped). Nothing on a log or a pipe, and
// nothing for a step that ends first.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace m3055 {

class SlowNote {
public:
    // After `after`, prints "m3055: STEP: WHY..." on `stream` when `interactive` (callers
    // pass isatty(stderr)).
    SlowNote(std::chrono::milliseconds after, std::string step, const std::string& why, bool interactive,
             std::FILE* stream = stderr);
    // The step succeeded: the end's line says "took" (else "stopped after").
    void finished() { finished_ = true; }
    // Ends the step: "m3055: STEP took N s" when the note was printed.
    ~SlowNote();
    SlowNote(const SlowNote&) = delete;
    SlowNote& operator=(const SlowNote&) = delete;

private:
    std::mutex mutex_;
    std::condition_variable ended_;
    bool done_ = false, printed_ = false, finished_ = false;
    std::string step_;
    std::FILE* stream_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::thread timer_;
};

// The note of a command that draws a scene on the GPU (`step`: "drawing", ...): after 3 s, on
// stderr when it is a terminal, with why a render may take that long.
SlowNote drawing_note(std::string step);

}  // namespace m3055
