#include "test_support.h"
#include "test_paths.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <chrono>


namespace m3055::test {

namespace fs = std::filesystem;

TempDir::TempDir() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern = std::string(base && *base ? base : "/tmp") + "/m3055-test-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (!mkdtemp(buffer.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = buffer.data();
}

TempDir::~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
}

Running::Running(const std::vector<std::string>& args) {
    const std::string out_path = capture_.file("stdout"), err_path = capture_.file("stderr");
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
        int out = open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int err = open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (out < 0 || err < 0) _exit(127);
        dup2(out, 1);
        dup2(err, 2);
        // Through the launcher, so the peak memory measured is m3055's own.
        std::vector<std::string> command = {M3055_MEASURE_CHILD, capture_.file("measured"), M3055_BINARY};
        command.insert(command.end(), args.begin(), args.end());
        std::vector<char*> argv;
        for (auto& a : command) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(argv[0], argv.data());
        _exit(127);
    }
}

Running::~Running() {
    if (reaped_ || pid_ <= 0) return;
    ::kill(pid_, SIGKILL);
    waitpid(pid_, &status_, 0);
}

void Running::signal(int number) const { ::kill(pid_, number); }

bool Running::finished() {
    if (!reaped_ && waitpid(pid_, &status_, WNOHANG) == pid_) reaped_ = true;
    return reaped_;
}

namespace {
// A file's text, or "" when it cannot be read (a /proc entry of a process that ended).
std::string read_text_if_any(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return file ? text.str() : std::string();
}
}  // namespace

bool Running::wait_for_gl_driver(double seconds) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    // The program is the launcher's child (measure_child).
    const std::string children = "/proc/" + std::to_string(pid_) + "/task/" + std::to_string(pid_) + "/children";
    while (std::chrono::steady_clock::now() < give_up && !finished()) {
        std::istringstream ids(read_text_if_any(children));
        for (std::string id; ids >> id;) {
            const std::string maps = read_text_if_any("/proc/" + id + "/maps");
            if (maps.find("swrast_dri") != std::string::npos || maps.find("libgallium") != std::string::npos ||
                maps.find("libOSMesa") != std::string::npos)
                return true;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
}

RunResult Running::wait() {
    if (!reaped_) waitpid(pid_, &status_, 0);
    reaped_ = true;
    RunResult result;
    result.exit_code = WIFEXITED(status_) ? WEXITSTATUS(status_) : 128 + WTERMSIG(status_);
    std::istringstream measured(read_text(capture_.file("measured")));
    long peak_kb = 0;
    measured >> result.seconds >> peak_kb >> result.killed_by;
    result.peak_rss_mib = double(peak_kb) / 1024.0;  // Linux: kilobytes
    result.out = read_text(capture_.file("stdout"));
    result.err = read_text(capture_.file("stderr"));
    return result;
}

RunResult run_m3055(const std::vector<std::string>& args) { return Running(args).wait(); }

void write_text(const std::string& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("cannot write " + path);
    file << text;
}

std::string read_text(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

bool file_exists(const std::string& path) { return fs::exists(path); }

std::map<std::string, std::string> snapshot(const std::string& folder, const std::string& except) {
    std::map<std::string, std::string> entries;
    for (auto it = fs::recursive_directory_iterator(folder); it != fs::recursive_directory_iterator(); ++it) {
        const std::string name = fs::relative(it->path(), folder).string();
        if (!except.empty() && name == except) {
            it.disable_recursion_pending();
            continue;
        }
        const fs::file_status status = it->symlink_status();
        if (fs::is_symlink(status)) entries[name] = "<link> " + fs::read_symlink(it->path()).string();
        else if (fs::is_regular_file(status)) entries[name] = read_text(it->path().string());
        else if (fs::is_directory(status)) entries[name] = "<folder>";
        else if (fs::is_fifo(status)) entries[name] = "<fifo>";
        else entries[name] = "<other>";
    }
    return entries;
}

std::string source_path(const std::string& relative) {
    return std::string(M3055_SOURCE_DIR) + "/" + relative;
}

std::string reference_image_path(const std::string& name) {
    return source_path("tests/data/reference-images/" + name);
}

}  // namespace m3055::test
