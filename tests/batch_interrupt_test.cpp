// Ctrl-C (SIGINT) and SIGTERM during `m3055 batch` (issue 6): the batch stops
// between scenes, exits 130 with one line saying how far it got, keeps every
// finished file whole, leaves no half-written file and no temporary file.
#include "image/image.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

namespace m3055::test {
namespace {

namespace fs = std::filesystem;

#ifndef M3055_BINARY
#error "M3055_BINARY comes from tests/CMakeLists.txt"
#endif

struct Finished {
    int exit_code = -1;  // 128 + signal when killed by one
    std::string err;
};

// Starts `m3055 batch MANIFEST`, sends `signal` once the first output file
// appears, and waits for the process.
Finished interrupt_batch(const std::string& manifest, const std::string& first_output,
                         const std::string& err_path, int signal) {
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        const int err = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null = open("/dev/null", O_WRONLY);
        if (err < 0 || null < 0) _exit(127);
        dup2(null, 1);
        dup2(err, 2);
        execl(M3055_BINARY, M3055_BINARY, "batch", manifest.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
    int status = 0;
    bool exited = false;
    while (!fs::exists(first_output) && std::chrono::steady_clock::now() < deadline) {
        if (waitpid(pid, &status, WNOHANG) == pid) {
            exited = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    if (!exited) {
        kill(pid, signal);
        waitpid(pid, &status, 0);
    }
    Finished finished;
    finished.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    finished.err = read_text(err_path);
    return finished;
}

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

    const Finished run = interrupt_batch(dir.file("manifest.json"), dir.file("out/0.png"), dir.file("err"), signal);
    EXPECT_EQ(run.exit_code, 130) << run.err;
    // The last stderr line says what happened (earlier lines are the progress).
    const std::string prefix = "m3055: interrupted by " + signal_name + ": ";
    const std::size_t at = run.err.rfind(prefix);
    ASSERT_NE(at, std::string::npos) << run.err;
    const std::size_t written = std::stoul(run.err.substr(at + prefix.size()));
    EXPECT_NE(run.err.find(" of 400 scenes written, the rest not started\n", at), std::string::npos) << run.err;
    EXPECT_GE(written, 1u);
    EXPECT_LT(written, std::size_t(kItems)) << "the batch finished before the signal";

    // Exactly the first `written` entries exist, each whole (PNG and, for odd
    // entries, PFM), and nothing else: no temporary file, no later entry.
    const Rgb8Image expected_png = read_png(dir.file("out/0.png"));
    std::vector<std::string> expected_names;
    for (std::size_t i = 0; i < written; ++i) {
        const std::string png = "out/" + std::to_string(i) + ".png";
        expected_names.push_back(std::to_string(i) + ".png");
        const Rgb8Image image = read_png(dir.file(png));
        EXPECT_EQ(image.width, 128) << png;
        EXPECT_EQ(image.pixels, expected_png.pixels) << png;
        if (i % 2) {
            expected_names.push_back(std::to_string(i) + ".pfm");
            const RgbFloatImage raw = read_pfm(dir.file("out/" + std::to_string(i) + ".pfm"));
            EXPECT_EQ(raw.pixels.size(), 128u * 80u * 3u) << i;
        }
    }
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir.file("out"))) names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    std::sort(expected_names.begin(), expected_names.end());
    EXPECT_EQ(names, expected_names);
}

TEST(BatchInterrupt, SigintKeepsFinishedFilesAndLeavesNoPartialOne) { check_interrupted_batch(SIGINT, "SIGINT"); }

TEST(BatchInterrupt, SigtermBehavesTheSame) { check_interrupted_batch(SIGTERM, "SIGTERM"); }

}  // namespace
}  // namespace m3055::test
