// Progress of a long command on stderr: on a terminal one line that updates in
// place (count, percent, rate); otherwise (a log file, a CI job) one plain line
// per step, so the log does not fill with carriage returns.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <string>

namespace m3055 {

class Progress {
public:
    // `interactive`: draw the updating bar (callers pass isatty(stderr)).
    Progress(std::size_t total, bool interactive, std::FILE* stream = stderr);
    // One step done; `label` names it (shown on plain lines), `error` is "" on success.
    void step(const std::string& label, const std::string& error);
    // Ends the bar's line (no-op for plain output).
    void finish();

private:
    void draw_bar();
    std::size_t total_, done_ = 0, failed_ = 0;
    bool interactive_;
    std::FILE* stream_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// "m3055: " + error as one line of valid UTF-8 of at most 300 bytes
// (io/message_text.h): how every command prints an error.
std::string error_line(const std::string& error);

// "[=======>      ]  37/200  18%  42.1 /s" for `width` bar characters.
std::string progress_line(std::size_t done, std::size_t total, double per_second, int width = 30);

}  // namespace m3055
