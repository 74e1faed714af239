// Mesa's shader cache on a full (or unwritable) disk. Mesa
// maps its cache index; on a full filesystem a write through the mapping was
// a SIGBUS that killed render and batch without a word. Now the run goes on
// without the cache, with a one-line note, and the same pixels; should a
// SIGBUS happen all the same, it ends in one line naming the cache.
#include "test_support.h"
#include "untrusted_harness.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <stdlib.h>
#include <sys/mount.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>
#include <utility>

namespace m3055::test {
namespace {

namespace fs = std::filesystem;

// Mesa's shader cache on for the m3055 runs of its lifetime, at `folder` when
// not empty (scripts/test-sanitize turns the cache off for the suite).
class WithShaderCache {
public:
    explicit WithShaderCache(const std::string& folder) {
        save("MESA_SHADER_CACHE_DIR", dir_);
        save("MESA_SHADER_CACHE_DISABLE", disable_);
        if (!folder.empty()) setenv("MESA_SHADER_CACHE_DIR", folder.c_str(), 1);
        unsetenv("MESA_SHADER_CACHE_DISABLE");
    }
    ~WithShaderCache() {
        restore("MESA_SHADER_CACHE_DIR", dir_);
        restore("MESA_SHADER_CACHE_DISABLE", disable_);
    }

private:
    static void save(const char* name, std::pair<bool, std::string>& into) {
        const char* value = std::getenv(name);
        into = {value != nullptr, value ? value : ""};
    }
    static void restore(const char* name, const std::pair<bool, std::string>& saved) {
        if (saved.first) setenv(name, saved.second.c_str(), 1);
        else unsetenv(name);
    }
    std::pair<bool, std::string> dir_, disable_;
};

// Renders the spec example with MESA_SHADER_CACHE_DIR=cache, by `render` and
// by `batch`: both succeed with the note, and give the same PNG as a render
// with the tests' own cache.
void expect_renders_without_cache(const std::string& cache) {
    TempDir dir;
    write_scene(dir.file("s.json"), "spec_example.json", 512, 320);
    write_text(dir.file("m.json"), R"([{"scene": "s.json", "out": "batch.png"}])");
    const RunResult normal = run_m3055({"render", "--scene", dir.file("s.json"), "--out", dir.file("normal.png")});
    ASSERT_EQ(normal.exit_code, 0) << normal.err;
    RunResult render, batch;
    {
        const WithShaderCache on(cache);
        render = run_m3055({"render", "--scene", dir.file("s.json"), "--out", dir.file("o.png")});
        batch = run_m3055({"batch", dir.file("m.json")});
    }
    const std::string note_start = "m3055: note: the Mesa shader cache " + cache + "/mesa_shader_cache ";
    const std::string note_end = ": shaders are compiled without it this run\n";
    for (const RunResult* run : {&render, &batch}) {
        EXPECT_EQ(run->exit_code, 0) << run->err;
        EXPECT_EQ(run->killed_by, 0);
        EXPECT_EQ(bad_lines(run->err), "");
        EXPECT_EQ(run->err.rfind(note_start, 0), 0u) << run->err;
        EXPECT_NE(run->err.find(note_end), std::string::npos) << run->err;
        expect_within(*run, Bounds{60, 256});
    }
    EXPECT_EQ(read_text(dir.file("o.png")), read_text(dir.file("normal.png")));
    EXPECT_EQ(read_text(dir.file("batch.png")), read_text(dir.file("normal.png")));
}

TEST(ShaderCache, FullDiskRunsWithoutTheCache) {
    TempDir dir;
    const std::string disk = dir.file("disk");
    fs::create_directory(disk);
    if (mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=64k") != 0)
        GTEST_SKIP() << "cannot mount a tmpfs here (" << std::strerror(errno) << "); UnwritableCache covers the check";
    {
        std::ofstream fill(disk + "/fill", std::ios::binary);
        const std::string block(4096, 'x');
        for (int i = 0; i < 64 && fill; ++i) fill << block;
    }
    expect_renders_without_cache(disk + "/cache");
    EXPECT_FALSE(fs::exists(disk + "/cache")) << "Mesa must not have been given the full disk";
    umount(disk.c_str());
}

TEST(ShaderCache, UnwritableCacheRunsWithoutIt) {
    // /proc takes no new files, even from root.
    if (!fs::exists("/proc/self")) GTEST_SKIP() << "no /proc";
    expect_renders_without_cache("/proc/m3055-no-cache");
}

// The last resort: a SIGBUS (here sent by hand, as Mesa's would arrive)
// ends the run with one line naming the cache, and removes the temporaries.
TEST(ShaderCache, BusErrorIsOneLineNamingTheCache) {
    TempDir dir;
    // Slow enough to be inside the render when the signal lands.
    write_stalling_scene(dir.file("slow.json"));
    const auto before = snapshot(dir.path());
    const WithShaderCache on("");  // so that the line can name it
    Running render({"render", "--scene", dir.file("slow.json"), "--out", dir.file("o.png")});
    ASSERT_TRUE(render.wait_for_gl_driver()) << "the render ended, or never made its context";
    std::this_thread::sleep_for(std::chrono::milliseconds(300));  // into the draws
    ASSERT_FALSE(render.finished());
    render.signal(SIGBUS);
    const RunResult run = render.wait();
    EXPECT_EQ(run.exit_code, 1);
    EXPECT_EQ(bad_lines(run.err), "");
    EXPECT_EQ(run.err.rfind("m3055: bus error (SIGBUS): a memory-mapped file could not be written; if the disk of "
                            "the Mesa shader cache ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find("MESA_SHADER_CACHE_DISABLE=true\n"), std::string::npos) << run.err;
    EXPECT_TRUE(snapshot(dir.path()) == before);
}

}  // namespace
}  // namespace m3055::test
