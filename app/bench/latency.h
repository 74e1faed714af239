// `m3055 bench`'s explorer latency section: a scripted session
// through every model, every light type and preset, 3 object additions and 50
// slider moves, each step timed from the edit to finished pixels (render +
// glFinish, as the explorer draws a frame), once compiling each new shader
// specialization before drawing (as the explorer first did) and once drawing
// with the general program while the specialized one waits for idle time.
#pragma once

#include "gl/context.h"

#include <string>

namespace m3055::bench {

struct LatencyStats {
    int steps = 0;
    double p50_ms = 0, p95_ms = 0, max_ms = 0;
    int compiles_in_steps = 0;       // programs built inside a timed step (a stall)
    int compiles_when_idle = 0;      // programs built between steps (idle time)
    double max_idle_compile_ms = 0;  // the longest idle re-render with new programs: an input arriving then waits up to this
};

struct LatencyReport {
    std::string device;
    LatencyStats before, after;
    std::string markdown() const;
};

// Runs the session twice on fresh renderers in a context of `backend`
// (Mesa's shader cache off, so every compile is paid).
LatencyReport explorer_latency(Backend backend);

}  // namespace m3055::bench
