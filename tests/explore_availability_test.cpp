// Whether `m3055 explore` is in the build, as the build says:
// - built with the explorer (-DM3055_BUILD_EXPLORER=ON, the default), the
//   subcommand has its options; scripts/run probes `explore --help` for them;
// - built without it (OFF: no GLFW, no ImGui), `m3055 explore` with any
//   arguments, and plain `m3055`, say in one line that this build has no
//   explorer and fail, writing nothing to stdout.
// tests/CMakeLists.txt sets M3055_TEST_HAVE_EXPLORER to the configuration;
// .ci/run builds both (scripts/test-noexplorer runs the second).
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#ifndef M3055_TEST_HAVE_EXPLORER
#error "tests/CMakeLists.txt defines M3055_TEST_HAVE_EXPLORER"
#endif

namespace m3055 {
namespace {

using test::run_m3055;

#if M3055_TEST_HAVE_EXPLORER

TEST(ExploreAvailability, ExplorerBuildListsTheExploreOptions) {
    const test::RunResult run = run_m3055({"explore", "--help"});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    for (const char* option : {"--scene", "--script", "--capture-window", "--window-size"})
        EXPECT_NE(run.out.find(option), std::string::npos) << option << " missing from\n" << run.out;
}

#else

std::size_t line_count(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

TEST(ExploreAvailability, ExploreSaysInOneLineThatThisBuildHasNoExplorer) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"explore"}, {"explore", "--help"},
          {"explore", "--scene", "scenes/fig05.json", "--script", "no such file"}}) {
        const test::RunResult run = run_m3055(args);
        EXPECT_EQ(run.exit_code, 1) << args.size();
        EXPECT_EQ(run.out, "") << args.size();
        EXPECT_EQ(line_count(run.err), 1u) << run.err;
        EXPECT_EQ(run.err.rfind("m3055: this build has no explorer", 0), 0u) << run.err;
        EXPECT_NE(run.err.find("M3055_BUILD_EXPLORER=OFF"), std::string::npos) << run.err;
    }
}

TEST(ExploreAvailability, PlainM3055EndsWithTheSameLine) {
    const test::RunResult run = run_m3055({});
    EXPECT_NE(run.exit_code, 0);
    const std::string last_line = run.err.substr(run.err.rfind('\n', run.err.size() - 2) + 1);
    EXPECT_EQ(last_line.rfind("m3055: this build has no explorer", 0), 0u) << run.err;
}

TEST(ExploreAvailability, OtherSubcommandsStillWork) {
    test::TempDir dir;
    const test::RunResult run = run_m3055({"render", "--scene", test::source_path("scenes/spec_example.json"),
                                           "--out", dir.file("spec.png")});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(test::file_exists(dir.file("spec.png")));
}

#endif

}  // namespace
}  // namespace m3055
