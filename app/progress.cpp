#include "progress.h"

#include "gl/program.h"
#include "io/message_text.h"

#include <cstdio>

namespace m3055 {

std::string error_line(const std::string& error) { return text::one_line("m3055: " + error); }

std::string progress_line(std::size_t done, std::size_t total, double per_second, int width) {
    const double fraction = total ? double(done) / double(total) : 1.0;
    const int filled = int(fraction * width);
    std::string bar = "[";
    for (int i = 0; i < width; ++i) bar += i < filled ? '=' : (i == filled ? '>' : ' ');
    bar += "]";
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, " %zu/%zu %3d%% %6.1f /s", done, total, int(fraction * 100.0 + 1e-9),
                  per_second);
    return bar + numbers;
}

Progress::Progress(std::size_t total, bool interactive, std::FILE* stream)
    : total_(total), interactive_(interactive), stream_(stream) {
    if (interactive_) draw_bar();
}

void Progress::draw_bar() {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double rate = seconds > 0 ? double(done_) / seconds : 0.0;
    std::string line = progress_line(done_, total_, rate);
    if (failed_) line += "  " + std::to_string(failed_) + " failed";
    // \r back to column 0, \033[K clears what a longer previous line left.
    std::fprintf(stream_, "\r%s\033[K", line.c_str());
    std::fflush(stream_);
}

void Progress::step(const std::string& label, const std::string& error) {
    ++done_;
    if (!error.empty()) ++failed_;
    if (interactive_) {
        // An error gets its own permanent line above the bar.
        if (!error.empty()) std::fprintf(stream_, "\r\033[K%s\n", error_line(error).c_str());
        draw_bar();
        return;
    }
    if (error.empty())
        std::fprintf(stream_, "[%zu/%zu] %s\n", done_, total_, text::quote_name(label).c_str());
    else
        std::fprintf(stream_, "%s\n", error_line(error).c_str());
    std::fflush(stream_);
}

void Progress::finish() {
    if (!interactive_) return;
    std::fprintf(stream_, "\n");
    std::fflush(stream_);
}

}  // namespace m3055
