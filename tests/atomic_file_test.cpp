// image/atomic_file.cpp against untrusted output names:
// only regular files or new names are written, a legal long name gets a
// temporary that fits, and every temporary is registered for an interrupt.
#include "image/image.h"
#include "image/temporary_files.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace m3055 {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

std::vector<std::string> entries(const std::string& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string error_of(const std::function<void()>& write) {
    try {
        write();
    } catch (const ImageError& error) {
        return error.what();
    }
    return "no error";
}

TEST(AtomicFile, FifoTargetIsAnErrorAndStaysAFifo) {
    TempDir dir;
    const std::string fifo = dir.file("out.png");
    ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
    EXPECT_EQ(error_of([&] { write_file_atomic(fifo, "x", 1); }),
              fifo + ": cannot write: it is a FIFO, not a regular file (outputs go only to regular files or new names)");
    struct stat info {};
    ASSERT_EQ(lstat(fifo.c_str(), &info), 0);
    EXPECT_TRUE(S_ISFIFO(info.st_mode));
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"out.png"});
}

TEST(AtomicFile, SymlinkTargetIsAnErrorAndItsTargetIsUntouched) {
    TempDir dir;
    test::write_text(dir.file("scene.json"), "precious");
    fs::create_symlink("scene.json", dir.file("out.png"));
    EXPECT_NE(error_of([&] { write_files_atomic({{dir.file("out.png"), {1, 2, 3}}}); }).find("it is a symbolic link"),
              std::string::npos);
    EXPECT_EQ(test::read_text(dir.file("scene.json")), "precious");
    EXPECT_TRUE(fs::is_symlink(dir.file("out.png")));
    EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"out.png", "scene.json"}));
}

TEST(AtomicFile, CharacterDeviceTargetIsAnError) {
    // /dev/null itself: as root, a rename over it would replace the device.
    struct stat before {};
    ASSERT_EQ(stat("/dev/null", &before), 0);
    EXPECT_NE(error_of([&] { write_file_atomic("/dev/null", "x", 1); }).find("it is a character device"),
              std::string::npos);
    struct stat after {};
    ASSERT_EQ(stat("/dev/null", &after), 0);
    EXPECT_TRUE(S_ISCHR(after.st_mode));
    EXPECT_EQ(before.st_ino, after.st_ino);
    for (const auto& entry : fs::directory_iterator("/dev"))
        EXPECT_EQ(entry.path().filename().string().rfind(".null.tmp-", 0), std::string::npos) << entry.path();
}

TEST(AtomicFile, LongestLegalNameGetsATemporaryThatFits) {
    TempDir dir;
    for (const std::size_t length : {250, 254, 255}) {
        const std::string name = std::string(length - 4, 'n') + ".png";
        write_files_atomic({{dir.file(name), {1, 2, 3}}, {dir.file(name.substr(0, length - 4) + ".pfm"), {4}}});
        EXPECT_EQ(test::read_text(dir.file(name)), std::string("\x01\x02\x03"));
    }
    // Multi-byte characters at the cut: the temporary's name stays valid UTF-8 (no error either way).
    std::string accented;
    while (accented.size() < 250) accented += "\xC3\xA9";
    write_file_atomic(dir.file(accented), "e", 1);
    EXPECT_EQ(test::read_text(dir.file(accented)), "e");
    EXPECT_EQ(entries(dir.path()).size(), 7u);  // no temporary left
}

TEST(AtomicFile, DeepPathBeyondPathMaxIsWrittenThroughItsFolder) {
    TempDir dir;
    // Folders whose full path is ~4090 bytes: the temporary's full path would be longer than PATH_MAX.
    std::string folder = dir.path();
    while (folder.size() < 4000) {
        folder += "/" + std::string(200, 'd');
        ASSERT_EQ(::mkdir(folder.c_str(), 0755), 0) << folder.size();
    }
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY);
    ASSERT_GE(fd, 0);
    ::close(fd);
    const std::string path = folder + "/" + std::string(4094 - folder.size() - 1, 'f');
    ASSERT_EQ(path.size(), 4094u);
    write_file_atomic(path, "deep", 4);
    EXPECT_EQ(test::read_text(path), "deep");
}

TEST(AtomicFile, CommittedRunsOnceEverythingIsInPlace) {
    TempDir dir;
    int calls = 0;
    write_files_atomic({{dir.file("a"), {1}}, {dir.file("b"), {2}}}, [&] {
        ++calls;
        EXPECT_TRUE(fs::exists(dir.file("a")));
        EXPECT_TRUE(fs::exists(dir.file("b")));
    });
    EXPECT_EQ(calls, 1);
    EXPECT_THROW(write_files_atomic({{dir.file("c"), {1}}, {dir.file("missing/d"), {2}}}, [&] { ++calls; }),
                 ImageError);
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(entries(dir.path()), (std::vector<std::string>{"a", "b"}));
}

TEST(AtomicFile, RemoveAllDeletesRegisteredTemporaries) {
    TempDir dir;
    const int folder = ::open(dir.path().c_str(), O_RDONLY | O_DIRECTORY);
    ASSERT_GE(folder, 0);
    test::write_text(dir.file(".x.tmp-abcdef"), "partial");
    test::write_text(dir.file("kept.png"), "finished");
    {
        std::lock_guard<std::mutex> hold(temporary_files::lock());
        temporary_files::add(folder, ".x.tmp-abcdef");
    }
    temporary_files::remove_all();
    temporary_files::remove_all();  // idempotent: the slot was freed
    ::close(folder);
    EXPECT_EQ(entries(dir.path()), std::vector<std::string>{"kept.png"});
}

}  // namespace
}  // namespace m3055
