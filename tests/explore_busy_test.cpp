// The line that says what the explorer is busy with
// (explore/busy.h), and the two steps of a watched .brdf file's reload: the
// poll that notices the change leaves "reloading FILE..." for a frame to
// show, the next poll reloads.
#include "explore/brdf_files.h"
#include "explore/busy.h"
#include "explore/files.h"
#include "explore/operations.h"
#include "explore/start.h"
#include "explore/undo.h"
#include "scene/presets.h"
#include "test_paths.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace m3055::explore {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(ExploreBusy, IdleSaysNothingAndDeferredProgramsSayCompiling) {
    ExplorerState state;
    EXPECT_EQ(busy_line(state, 0), "");
    EXPECT_EQ(busy_line(state, 2), "compiling...");
}

TEST(ExploreBusy, AChangedBrdfFileIsShownAsReloadingBeforeItIsReloaded) {
    const fs::path dir = fs::path(::testing::TempDir()) / "explore_busy";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path file = dir / "mine.brdf";
    const std::string text = read(test::source_path("tests/data/brdf/lambert.brdf"));
    ASSERT_FALSE(text.empty());
    { std::ofstream(file) << text; }
    ExplorerState state;
    set_scene(state, default_scene(), "spec example");
    start_history(state);
    ASSERT_TRUE(open_brdf(state, file.string())) << state.brdf_error;
    double now = 100.0;
    EXPECT_FALSE(poll_brdf_files(state, now)) << "unchanged";
    // Another size: the stamp (mtime and size) differs even within the same second.
    { std::ofstream(file) << text << "\n# edited\n"; }
    now += 10.0;
    state.status.clear();
    EXPECT_TRUE(poll_brdf_files(state, now)) << "noticed";
    EXPECT_EQ(busy_line(state, 0), "reloading mine.brdf...");
    EXPECT_EQ(state.status, "") << "not reloaded yet: a frame shows the line first";
    EXPECT_TRUE(poll_brdf_files(state, now + 0.01)) << "reloaded at once, whatever the poll period";
    EXPECT_EQ(busy_line(state, 0), "");
    EXPECT_NE(state.status.find("reloaded"), std::string::npos) << state.status;
    EXPECT_FALSE(poll_brdf_files(state, now + 0.02));
}

}  // namespace
}  // namespace m3055::explore
