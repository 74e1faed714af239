#include "untrusted_harness.h"

#include "sanitized.h"

#include "io/message_text.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

namespace m3055::test {

// Processes run several times slower and larger under the sanitizers.
const double kSanitizerSlack = kSanitized ? 6.0 : 1.0;

void expect_within(const RunResult& run, const Bounds& bounds) {
    EXPECT_LE(run.seconds, bounds.seconds * kSanitizerSlack);
    EXPECT_LE(run.peak_rss_mib, bounds.peak_rss_mib * kSanitizerSlack);
}

std::string bad_lines(const std::string& err) {
    if (!text::is_valid_utf8(err)) return "stderr is not valid UTF-8";
    std::istringstream lines(err);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.size() > text::kMaxLineBytes) return "a line of " + std::to_string(line.size()) + " bytes";
        for (const unsigned char c : line)
            if (c < 0x20 || c == 0x7F) return "a control character in: " + text::escape(line);
    }
    if (!err.empty() && err.back() != '\n') return "the last line does not end";
    return "";
}

bool glob_match(const std::string& pattern, const std::string& text) {
    // Iterative '*' matching with backtracking to the last star.
    std::size_t p = 0, t = 0, star = std::string::npos, mark = 0;
    while (t < text.size()) {
        if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            mark = t;
        } else if (p < pattern.size() && pattern[p] == text[t]) {
            ++p, ++t;
        } else if (star != std::string::npos) {
            p = star + 1;
            t = ++mark;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

RunResult expect_refused(const std::string& folder, const std::vector<std::string>& args, int exit_code,
                         const std::string& err, const Bounds& bounds) {
    const auto before = snapshot(folder);
    const RunResult run = run_m3055(args);
    EXPECT_EQ(run.exit_code, exit_code) << run.err;
    if (err.find('*') == std::string::npos) EXPECT_EQ(run.err, err);
    else EXPECT_TRUE(glob_match(err, run.err)) << text::escape(run.err.substr(0, 2000)) << "\ndoes not match\n" << err;
    EXPECT_EQ(bad_lines(run.err), "") << text::escape(run.err.substr(0, 2000));
    EXPECT_TRUE(snapshot(folder) == before) << "a file was created, changed or left behind";
    expect_within(run, bounds);
    return run;
}

void write_scene(const std::string& path, const std::string& name, int width, int height) {
    nlohmann::json doc = nlohmann::json::parse(read_text(source_path("scenes/" + name)));
    if (width > 0) doc["display"] = {{"width", width}, {"height", height}, {"bits", 5}};
    write_text(path, doc.dump(2));
}

void write_stalling_scene(const std::string& path, int width, int height, int spheres) {
    nlohmann::json scene = nlohmann::json::parse(read_text(source_path("scenes/spec_example.json")));
    scene["display"] = {{"width", width}, {"height", height}, {"bits", 5}};
    scene["lights"] = nlohmann::json::array();
    for (int i = 0; i < 16; ++i)
        scene["lights"].push_back({{"type", "spot"}, {"position", {0.1 * i, 0.2, 4}}, {"spot_direction", {0, 0, -1}},
                                   {"spot_exponent", 2}});
    scene["objects"] = nlohmann::json::array();
    for (int i = 0; i < spheres; ++i)
        scene["objects"].push_back({{"shape", "sphere"}, {"center", {0, 0, -0.001 * i}}, {"radius", 3},
                                    {"material", {{"model", "translucent"}, {"color", {0.5, 0.5, 0.5}}}}});
    write_text(path, scene.dump());
}

}  // namespace m3055::test
