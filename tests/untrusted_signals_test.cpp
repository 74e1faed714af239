// SIGINT, SIGTERM and SIGHUP handled alike by `render` and
// `batch`, wherever they land (during a write, during a slow scene):
// temporaries removed, finished files kept, the process ended by the signal
// within about a second, one line saying how far it got.
#include "test_support.h"
#include "untrusted_harness.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <stdlib.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

namespace m3055::test {
namespace {

// The stalls and write pauses below last 20 s: ending well before that means
// the signal ended the run, not the scene finishing. (Not a speed check: a
// loaded machine may take seconds to schedule the exit.)
constexpr double kEndedBySignal = 10.0;

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Waits until `ready()` (or the process ends, or a minute passes).
template <class Ready>
void wait_for(Running& run, Ready ready) {
    const auto deadline = Clock::now() + std::chrono::minutes(1);
    while (!ready() && !run.finished() && Clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
}

bool has_temporary(const std::string& folder) {
    for (const auto& entry : fs::directory_iterator(folder))
        if (entry.path().filename().string().find(".tmp-") != std::string::npos) return true;
    return false;
}

// Sends `signal` and returns the result with the seconds from signal to exit.
RunResult interrupt(Running& run, int signal, double& seconds_after) {
    const auto sent = Clock::now();
    run.signal(signal);
    RunResult result = run.wait();
    seconds_after = std::chrono::duration<double>(Clock::now() - sent).count();
    return result;
}

class RenderSignal : public ::testing::TestWithParam<int> {};

TEST_P(RenderSignal, DuringTheWriteRemovesTemporariesAndKeepsOldFiles) {
    const int signal = GetParam();
    TempDir dir;
    write_scene(dir.file("s.json"));
    write_text(dir.file("o.png"), "old png");
    write_text(dir.file("o.pfm"), "old pfm");
    const auto before = snapshot(dir.path());
    setenv("M3055_FAULT_WRITE_PAUSE_MS", "20000", 1);  // test-only: temporaries stay 20 s
    Running render({"render", "--scene", dir.file("s.json"), "--out", dir.file("o.png"), "--raw", dir.file("o.pfm")});
    unsetenv("M3055_FAULT_WRITE_PAUSE_MS");
    wait_for(render, [&] { return has_temporary(dir.path()); });
    ASSERT_TRUE(has_temporary(dir.path())) << "the render ended before writing";
    double after = 0;
    const RunResult run = interrupt(render, signal, after);
    EXPECT_EQ(run.exit_code, 128 + signal);
    EXPECT_EQ(run.killed_by, signal);
    EXPECT_EQ(run.err, "m3055: interrupted by " + std::string(signal == SIGINT    ? "SIGINT"
                                                              : signal == SIGTERM ? "SIGTERM"
                                                                                  : "SIGHUP") +
                           ": nothing written\n");
    EXPECT_LT(after, kEndedBySignal);
    expect_within(run, Bounds{60, 256});
    EXPECT_TRUE(snapshot(dir.path()) == before) << "a temporary was left or an old file changed";
}

TEST_P(RenderSignal, DuringASlowSceneEndsWithoutFinishingIt) {
    const int signal = GetParam();
    TempDir dir;
    write_stalling_scene(dir.file("slow.json"));
    const auto before = snapshot(dir.path());
    Running render({"render", "--scene", dir.file("slow.json"), "--out", dir.file("o.png")});
    ASSERT_TRUE(render.wait_for_gl_driver()) << "the render ended, or never made its context";
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // into the draws
    ASSERT_FALSE(render.finished());
    double after = 0;
    const RunResult run = interrupt(render, signal, after);
    EXPECT_EQ(run.exit_code, 128 + signal);
    EXPECT_EQ(bad_lines(run.err), "");
    EXPECT_NE(run.err.find(": nothing written\n"), std::string::npos) << run.err;
    EXPECT_LT(after, kEndedBySignal);
    EXPECT_TRUE(snapshot(dir.path()) == before);
}

INSTANTIATE_TEST_SUITE_P(Untrusted, RenderSignal, ::testing::Values(SIGINT, SIGTERM, SIGHUP),
                         [](const ::testing::TestParamInfo<int>& info) {
                             return info.param == SIGINT ? "sigint" : info.param == SIGTERM ? "sigterm" : "sighup";
                         });

// `timeout` sends SIGTERM: the batch must not wait for the scene in progress.
TEST(BatchSignal, SigtermDuringASlowSceneKeepsWhatWasWrittenAndEndsAtOnce) {
    TempDir dir;
    write_scene(dir.file("quick.json"));
    write_stalling_scene(dir.file("slow.json"));
    write_text(dir.file("m.json"), R"([{"scene": "quick.json", "out": "quick.png", "raw": "quick.pfm"},
        {"scene": "slow.json", "out": "slow.png"}, {"scene": "quick.json", "out": "after.png"}])");
    Running batch({"batch", dir.file("m.json")});
    wait_for(batch, [&] { return fs::exists(dir.file("quick.pfm")); });
    std::this_thread::sleep_for(std::chrono::milliseconds(1000));  // inside the slow scene
    ASSERT_FALSE(batch.finished());
    double after = 0;
    const RunResult run = interrupt(batch, SIGTERM, after);
    EXPECT_EQ(run.exit_code, 128 + SIGTERM);
    EXPECT_EQ(bad_lines(run.err), "");
    const std::string last = "m3055: interrupted by SIGTERM: 1 of 3 scenes written, the rest not\n";
    ASSERT_GE(run.err.size(), last.size());
    EXPECT_EQ(run.err.substr(run.err.size() - last.size()), last) << run.err;
    EXPECT_LT(after, kEndedBySignal);
    EXPECT_TRUE(fs::exists(dir.file("quick.png")));
    EXPECT_FALSE(fs::exists(dir.file("slow.png")));
    EXPECT_FALSE(fs::exists(dir.file("after.png")));
    EXPECT_FALSE(has_temporary(dir.path()));
}

TEST(BatchSignal, SighupDuringAWriteRemovesBothTemporaries) {
    TempDir dir;
    write_scene(dir.file("s.json"));
    write_text(dir.file("m.json"), R"([{"scene": "s.json", "out": "a.png", "raw": "a.pfm"},
        {"scene": "s.json", "out": "b.png", "raw": "b.pfm"}])");
    setenv("M3055_FAULT_WRITE_PAUSE_MS", "20000", 1);
    Running batch({"batch", dir.file("m.json")});
    unsetenv("M3055_FAULT_WRITE_PAUSE_MS");
    wait_for(batch, [&] { return has_temporary(dir.path()); });
    double after = 0;
    const RunResult run = interrupt(batch, SIGHUP, after);
    EXPECT_EQ(run.exit_code, 128 + SIGHUP);
    EXPECT_EQ(run.err, "m3055: interrupted by SIGHUP: 0 of 2 scenes written, the rest not\n");
    EXPECT_LT(after, kEndedBySignal);
    EXPECT_FALSE(has_temporary(dir.path()));
    EXPECT_EQ(snapshot(dir.path()).size(), 2u);  // the scene and the manifest, nothing else
}

}  // namespace
}  // namespace m3055::test
