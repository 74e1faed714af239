#include "slow_note.h"

#include "progress.h"

#include <unistd.h>

namespace m3055 {

SlowNote::SlowNote(std::chrono::milliseconds after, std::string step, const std::string& why, bool interactive,
                   std::FILE* stream)
    : step_(std::move(step)), stream_(stream) {
    if (!interactive) return;
    timer_ = std::thread([this, after, what = step_ + ": " + why] {
        std::unique_lock<std::mutex> lock(mutex_);
        if (ended_.wait_for(lock, after, [this] { return done_; })) return;
        std::fprintf(stream_, "%s...\n", error_line(what).c_str());
        std::fflush(stream_);
        printed_ = true;
    });
}

SlowNote::~SlowNote() {
    if (!timer_.joinable()) return;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        done_ = true;
    }
    ended_.notify_one();
    timer_.join();
    if (!printed_) return;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::fprintf(stream_, "%s %s %.0f s\n", error_line(step_).c_str(), finished_ ? "took" : "stopped after", seconds);
    std::fflush(stream_);
}

SlowNote drawing_note(std::string step) {
    return SlowNote(std::chrono::seconds(3), std::move(step),
                    "on Mesa's CPU renderer (llvmpipe) area lights and shadows take up to minutes, and a scene's "
                    "new shaders a minute to compile (once: Mesa caches them)",
                    isatty(STDERR_FILENO) == 1);
}

}  // namespace m3055
