// The line that says what the explorer is busy with
// (explore/busy.h), and the two steps of a watched .brdf file's reload: the
// poll that notices the change leaves "reloading FILE..." for a frame to
// show, and the reload itself when the frame loop is idle (reload_changed_brdf_files).
#include "explore/apply.h"
#include "explore/brdf_files.h"
#include "explore/busy.h"
#include "explore/files.h"
#include "explore/operations.h"
#include "explore/start.h"
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
    const BrdfWatch watch;
    EXPECT_EQ(busy_line(watch, 0), "");
    EXPECT_EQ(busy_line(watch, 2), "compiling...");
}

TEST(ExploreBusy, APreviewOfAreaLightsSaysRefiningUntilItShowsTheRendersPixels) {
    const BrdfWatch watch;
    EXPECT_EQ(busy_line(watch, 0, true), "refining...");
    EXPECT_EQ(busy_line(watch, 2, true), "refining...") << "refining draws with the specialized program too";
    EXPECT_EQ(busy_line(watch, 0, false), "");
}

TEST(ExploreBusy, AChangedBrdfFileIsShownAsReloadingBeforeItIsReloaded) {
    const fs::path dir = fs::path(::testing::TempDir()) / "explore_busy";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path file = dir / "mine.brdf";
    const std::string text = read(test::source_path("tests/data/brdf/lambert.brdf"));
    ASSERT_FALSE(text.empty());
    { std::ofstream(file) << text; }
    Explorer explorer;
    set_scene(explorer, default_scene(), "spec example");
    start_history(explorer);
    ASSERT_TRUE(run_command(explorer, command::OpenBrdf{file.string()})) << explorer.session.messages.brdf_error;
    double now = 100.0;
    EXPECT_FALSE(poll_brdf_files(explorer, now)) << "unchanged";
    // Another size: the stamp (mtime and size) differs even within the same second.
    { std::ofstream(file) << text << "\n# edited\n"; }
    now += 10.0;
    explorer.session.messages.status.clear();
    EXPECT_TRUE(poll_brdf_files(explorer, now)) << "noticed";
    EXPECT_EQ(busy_line(explorer.session.brdf_watch, 0), "reloading mine.brdf...");
    EXPECT_EQ(explorer.session.messages.status, "") << "not reloaded yet: frames show the line and the last version";
    EXPECT_FALSE(poll_brdf_files(explorer, now + 10.0)) << "polls wait for the reload";
    EXPECT_EQ(explorer.session.messages.status, "") << "a poll never reloads: the frame loop does, when idle";
    EXPECT_TRUE(reload_changed_brdf_files(explorer));
    EXPECT_EQ(busy_line(explorer.session.brdf_watch, 0), "");
    EXPECT_NE(explorer.session.messages.status.find("reloaded"), std::string::npos) << explorer.session.messages.status;
    EXPECT_FALSE(reload_changed_brdf_files(explorer)) << "nothing left";
    EXPECT_FALSE(poll_brdf_files(explorer, now + 20.0));
}

}  // namespace
}  // namespace m3055::explore
