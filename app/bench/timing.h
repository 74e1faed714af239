// Repeated timing with warm-up: median, min and max in milliseconds.
#pragma once

#include <functional>
#include <vector>

namespace m3055::bench {

struct TimeStats {
    double median_ms = 0, min_ms = 0, max_ms = 0;
    int repetitions = 0;
    bool valid() const { return repetitions > 0; }
};

TimeStats summarize(std::vector<double> samples_ms);

// Runs `once` warm_up times untimed, then `repetitions` times; `once` returns
// the milliseconds it measured itself (so it can exclude setup it does).
TimeStats measure(int warm_up, int repetitions, const std::function<double()>& once);

// Milliseconds `work` takes on the steady clock.
double time_ms(const std::function<void()>& work);

}  // namespace m3055::bench
