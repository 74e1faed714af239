// `m3055 bench --latency` (app/bench/latency.h): the scripted
// explorer session's table. No timed assertion (benchmarks report): the
// properties are the session's length and where the compiles happen -- before,
// inside the steps (the stall); after, none inside a step, all when idle.
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

namespace m3055 {
namespace {

TEST(ExplorerLatency, AfterTheChangeNoStepCompilesAProgram) {
    test::TempDir dir;
    const test::RunResult run = test::run_m3055({"bench", "--latency", "--out", dir.path()});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const std::string md = test::read_text(dir.file("latency.md"));
    EXPECT_NE(run.out.find(md), std::string::npos) << "the table is printed too";
    int before_steps = 0, before_in_steps = 0, after_steps = 0, after_in_steps = 0, after_idle = 0;
    std::istringstream lines(md);
    for (std::string line; std::getline(lines, line);) {
        double p50, p95, max, idle_ms;
        int steps, in_steps, idle;
        const auto cells = line.find(" | ", 2);
        if (cells == std::string::npos ||
            std::sscanf(line.c_str() + cells, " | %d | %lf | %lf | %lf | %d | %d | %lf |", &steps, &p50, &p95, &max,
                        &in_steps, &idle, &idle_ms) != 7)
            continue;
        EXPECT_LE(p50, p95) << line;
        EXPECT_LE(p95, max) << line;
        if (line.rfind("| before", 0) == 0) before_steps = steps, before_in_steps = in_steps;
        if (line.rfind("| after", 0) == 0) after_steps = steps, after_in_steps = in_steps, after_idle = idle;
    }
    EXPECT_GE(before_steps, 1 + 3 + 4 + 3 + 50) << md;  // models, light types, presets, objects, slider moves
    EXPECT_EQ(after_steps, before_steps);
    EXPECT_GT(before_in_steps, 0) << "new specializations are compiled inside steps without deferral";
    EXPECT_EQ(after_in_steps, 0) << "with deferral no step compiles";
    EXPECT_EQ(after_idle, before_in_steps) << "the same programs, built when idle";
}

}  // namespace
}  // namespace m3055
