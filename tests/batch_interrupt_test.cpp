// Ctrl-C (SIGINT), SIGTERM and SIGHUP during `m3055 batch`:
// the batch ends at once by the signal with one line saying how far it got,
// keeps every finished file whole (a PNG and its PFM together), and leaves no
// half-written file and no temporary file. tests/untrusted_signals_test.cpp
// has the cases where the signal lands during a write or a slow scene.
#include "image/image.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>

#include <chrono>
#include <filesystem>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace m3055::test {
namespace {

namespace fs = std::filesystem;

void check_interrupted_batch(int signal, const std::string& signal_name) {
    TempDir dir;
    // Many small renders of one scene: each takes milliseconds, so the signal
    // lands while the batch is busy, long before its end.
    nlohmann::json scene = nlohmann::json::parse(read_text(source_path("scenes/spec_example.json")));
    scene["display"] = {{"width", 128}, {"height", 80}, {"bits", 5}};
    write_text(dir.file("scene.json"), scene.dump());
    constexpr int kItems = 400;
    nlohmann::json manifest = nlohmann::json::array();
    for (int i = 0; i < kItems; ++i) {
        nlohmann::json entry = {{"scene", "scene.json"}, {"out", "out/" + std::to_string(i) + ".png"}};
        if (i % 2) entry["raw"] = "out/" + std::to_string(i) + ".pfm";
        manifest.push_back(entry);
    }
    fs::create_directory(dir.file("out"));
    write_text(dir.file("manifest.json"), manifest.dump());

    Running batch({"batch", dir.file("manifest.json")});
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
    while (!fs::exists(dir.file("out/0.png")) && !batch.finished() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    batch.signal(signal);
    const RunResult run = batch.wait();
    // Ended at once: by the signal, and before the batch's end (written < 400 below).
    EXPECT_EQ(run.exit_code, 128 + signal) << run.err;
    EXPECT_EQ(run.killed_by, signal) << "ended by the signal itself, so a shell's loop stops too";
    // The last stderr line says what happened (earlier lines are the progress).
    const std::string prefix = "m3055: interrupted by " + signal_name + ": ";
    const std::size_t at = run.err.rfind(prefix);
    ASSERT_NE(at, std::string::npos) << run.err;
    const std::size_t written = std::stoul(run.err.substr(at + prefix.size()));
    EXPECT_EQ(run.err.substr(at + prefix.size() + std::to_string(written).size()),
              " of 400 scenes written, the rest not\n")
        << run.err;
    EXPECT_GE(written, 1u);
    EXPECT_LT(written, std::size_t(kItems)) << "the batch finished before the signal";

    // Exactly `written` entries exist, each whole (PNG and, for odd entries,
    // PFM), and nothing else: no temporary file, no PNG without its PFM.
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir.file("out"))) names.insert(entry.path().filename());
    const Rgb8Image expected_png = read_png(dir.file("out/0.png"));
    std::size_t complete = 0;
    for (int i = 0; i < kItems; ++i) {
        const std::string png = std::to_string(i) + ".png", pfm = std::to_string(i) + ".pfm";
        if (!names.count(png)) {
            EXPECT_FALSE(names.count(pfm)) << pfm << " without its PNG";
            continue;
        }
        ++complete;
        names.erase(png);
        EXPECT_EQ(read_png(dir.file("out/" + png)).pixels, expected_png.pixels) << png;
        if (i % 2) {
            ASSERT_TRUE(names.count(pfm)) << png << " without its PFM";
            names.erase(pfm);
            EXPECT_EQ(read_pfm(dir.file("out/" + pfm)).pixels.size(), 128u * 80u * 3u) << pfm;
        }
    }
    EXPECT_EQ(complete, written);
    EXPECT_TRUE(names.empty()) << "left behind: " << *names.begin();
}

TEST(BatchInterrupt, SigintKeepsFinishedFilesAndLeavesNoPartialOne) { check_interrupted_batch(SIGINT, "SIGINT"); }

TEST(BatchInterrupt, SigtermBehavesTheSame) { check_interrupted_batch(SIGTERM, "SIGTERM"); }

TEST(BatchInterrupt, SighupBehavesTheSame) { check_interrupted_batch(SIGHUP, "SIGHUP"); }

}  // namespace
}  // namespace m3055::test
