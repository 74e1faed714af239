// Failure paths of the output files (docs/spec.md#8-command-line): an output folder that is
// missing, is really a file, or cannot be written; a disk that fills up while
// writing. Every case: exit 1, one line naming the file and the reason, an
// existing output untouched, no temporary file left, and no PNG written when
// the PFM of the same run failed.
#include "test_support.h"

#include <gtest/gtest.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace m3055::test {
namespace {

namespace fs = std::filesystem;

std::string spec_scene() { return source_path("scenes/spec_example.json"); }

bool one_line(const std::string& text) { return !text.empty() && text.find('\n') == text.size() - 1; }

// Names in `folder`, sorted: also shows any ".NAME.tmp-XXXXXX" left behind.
std::vector<std::string> names_in(const std::string& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

void expect_failure(const RunResult& run, const std::string& path, const std::string& reason) {
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_TRUE(one_line(run.err)) << run.err;
    EXPECT_NE(run.err.find(path), std::string::npos) << path << " not in " << run.err;
    EXPECT_NE(run.err.find(reason), std::string::npos) << run.err;
}

TEST(OutputFailures, MissingOutputFolder) {
    TempDir dir;
    const std::string out = dir.file("missing/out.png");
    const RunResult run = run_m3055({"render", "--scene", spec_scene(), "--out", out});
    expect_failure(run, out, "No such file or directory");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{});
}

TEST(OutputFailures, OutputFolderIsARegularFile) {
    TempDir dir;
    write_text(dir.file("file"), "not a folder");
    const std::string out = dir.file("file/out.png");
    const RunResult run = run_m3055({"render", "--scene", spec_scene(), "--out", out});
    expect_failure(run, out, "Not a directory");
    EXPECT_EQ(read_text(dir.file("file")), "not a folder");
}

// Root may write anywhere a mode bit forbids, so the unwritable folder is one
// the kernel refuses: sysfs does not allow creating files, even for root.
TEST(OutputFailures, OutputFolderNotWritable) {
    if (!fs::exists("/sys/kernel")) GTEST_SKIP() << "no sysfs at /sys";
    const std::string out = "/sys/m3055-out.png";
    const RunResult run = run_m3055({"render", "--scene", spec_scene(), "--out", out});
    expect_failure(run, out, "cannot create temporary file: Permission denied");
    EXPECT_FALSE(file_exists(out));
}

TEST(OutputFailures, OutputFolderWithoutWritePermission) {
    if (geteuid() == 0) GTEST_SKIP() << "root ignores mode bits (OutputFolderNotWritable covers this as root)";
    TempDir dir;
    const std::string folder = dir.file("read-only");
    fs::create_directory(folder);
    write_text(folder + "/out.png", "old");
    chmod(folder.c_str(), 0555);
    const RunResult run = run_m3055({"render", "--scene", spec_scene(), "--out", folder + "/out.png"});
    chmod(folder.c_str(), 0755);
    expect_failure(run, folder + "/out.png", "Permission denied");
    EXPECT_EQ(read_text(folder + "/out.png"), "old");
}

TEST(OutputFailures, UnwritableRawLeavesTheExistingPngAlone) {
    TempDir dir;
    write_text(dir.file("out.png"), "old png");
    const std::string raw = dir.file("missing/out.pfm");
    const RunResult run = run_m3055({"render", "--scene", spec_scene(), "--out", dir.file("out.png"), "--raw", raw});
    expect_failure(run, raw, "No such file or directory");
    EXPECT_EQ(read_text(dir.file("out.png")), "old png");
    EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out.png"});
}

// The disk fills up while writing the PNG and the PFM (1.9 MB, whichever hits
// the limit): both old files survive (neither is renamed over its target
// until both are written), and the partial temporary files are gone.
void expect_disk_full_keeps_old_files(const std::string& folder) {
    write_text(folder + "/out.png", "old png");
    write_text(folder + "/out.pfm", "old pfm");
    const RunResult run = run_m3055(
        {"render", "--scene", spec_scene(), "--out", folder + "/out.png", "--raw", folder + "/out.pfm"});
    expect_failure(run, folder + "/out.p", "No space left on device");
    EXPECT_EQ(read_text(folder + "/out.png"), "old png");
    EXPECT_EQ(read_text(folder + "/out.pfm"), "old pfm");
    EXPECT_EQ(names_in(folder), (std::vector<std::string>{"out.pfm", "out.png"}));
}

// A real full disk: a 64 KiB tmpfs. Needs mount privileges (CAP_SYS_ADMIN);
// DiskFullByFaultInjection covers the same path everywhere else.
TEST(OutputFailures, DiskFullOnSmallTmpfs) {
    TempDir dir;
    const std::string folder = dir.file("small");
    fs::create_directory(folder);
    if (mount("tmpfs", folder.c_str(), "tmpfs", 0, "size=64k") != 0)
        GTEST_SKIP() << "cannot mount a tmpfs here (" << std::strerror(errno) << ")";
    expect_disk_full_keeps_old_files(folder);
    // A PNG alone fits: the same folder still takes a whole, valid file.
    const RunResult png = run_m3055({"render", "--scene", spec_scene(), "--out", folder + "/new.png"});
    EXPECT_EQ(png.exit_code, 0) << png.err;
    umount(folder.c_str());
}

TEST(OutputFailures, DiskFullByFaultInjection) {
    TempDir dir;
    setenv("M3055_FAULT_WRITE_AFTER_BYTES", "1000", 1);  // test-only hook in write_file_atomic
    expect_disk_full_keeps_old_files(dir.path());
    // The PNG's own write failing: the old PNG survives too.
    const RunResult run = run_m3055({"render", "--scene", spec_scene(), "--out", dir.file("out.png")});
    unsetenv("M3055_FAULT_WRITE_AFTER_BYTES");
    expect_failure(run, dir.file("out.png"), "No space left on device");
    EXPECT_EQ(read_text(dir.file("out.png")), "old png");
    EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"out.pfm", "out.png"}));
    // Without the hook the same command succeeds: the failure was the injected one.
    const RunResult ok = run_m3055({"render", "--scene", spec_scene(), "--out", dir.file("out.png")});
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_NE(read_text(dir.file("out.png")), "old png");
}

}  // namespace
}  // namespace m3055::test
