// What every hostile-input test asserts:
// the exit status, the message (every stderr line one line of valid UTF-8,
// at most 300 bytes), no file created, every pre-existing file byte-identical,
// no temporary left, and bounds on time and peak memory measured through
// getrusage of the child (tests/support/measure_child.c). The bounds are
// generous: these are not speed tests.
#pragma once

#include "test_support.h"

#include <map>
#include <string>
#include <vector>

namespace m3055::test {

// The bounds of a Release build. Under AddressSanitizer (scripts/test-sanitize)
// they are scaled by kSanitizerSlack: its shadow memory, redzones and 256 MiB
// quarantine make the same run take about 4 to 5 times the memory (the late
// rejection: 216 MiB in Release, 989 MiB with ASan) and several times the time.
struct Bounds {
    double seconds = 60;
    double peak_rss_mib = 256;
};
extern const double kSanitizerSlack;  // 1 in Release

// Expects `run` within `bounds` (scaled under a sanitizer).
void expect_within(const RunResult& run, const Bounds& bounds);

// "" when every line of `err` is valid UTF-8 without control characters and
// at most 300 bytes, else what is wrong.
std::string bad_lines(const std::string& err);

// True when `text` matches `pattern`, where '*' stands for any run of bytes.
bool glob_match(const std::string& pattern, const std::string& text);

// Runs m3055 `args` with `folder` watched: asserts exit `exit_code`, stderr
// exactly `err` (or matching it as a glob_match pattern when it holds a '*';
// each line checked by bad_lines), the folder's snapshot unchanged, and
// `bounds`. Returns the run for further checks.
RunResult expect_refused(const std::string& folder, const std::vector<std::string>& args, int exit_code,
                         const std::string& err, const Bounds& bounds = {});

// A copy of scenes/NAME (display resized when width > 0) written to `path`.
void write_scene(const std::string& path, const std::string& name = "spec_example.json", int width = 64,
                 int height = 40);

// A legal scene that stalls a renderer: `spheres`
// overlapping screen-filling translucent spheres under 16 spot lights. 20 000
// take minutes at 512 x 320, far over any time budget the tests give. (The
// object limit, 100 000, took 8 s to load in the sanitizer build before a
// budget's clock starts; scene_loader_test checks the limit itself.)
void write_stalling_scene(const std::string& path, int width = 512, int height = 320, int spheres = 20000);

}  // namespace m3055::test
