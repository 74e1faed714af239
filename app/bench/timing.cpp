#include "timing.h"

#include <algorithm>
#include <chrono>

namespace m3055::bench {

TimeStats summarize(std::vector<double> samples_ms) {
    TimeStats stats;
    if (samples_ms.empty()) return stats;
    std::sort(samples_ms.begin(), samples_ms.end());
    const std::size_t n = samples_ms.size();
    stats.median_ms = n % 2 ? samples_ms[n / 2] : 0.5 * (samples_ms[n / 2 - 1] + samples_ms[n / 2]);
    stats.min_ms = samples_ms.front();
    stats.max_ms = samples_ms.back();
    stats.repetitions = int(n);
    return stats;
}

TimeStats measure(int warm_up, int repetitions, const std::function<double()>& once) {
    for (int i = 0; i < warm_up; ++i) once();
    std::vector<double> samples;
    for (int i = 0; i < repetitions; ++i) samples.push_back(once());
    return summarize(samples);
}

double time_ms(const std::function<void()>& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace m3055::bench
