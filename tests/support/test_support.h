// Small helpers shared by the tests: temporary folders and running the m3055
// executable as a separate process (to check exit codes, stderr and files).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace m3055::test {

// A fresh, empty folder under $TMPDIR (or /tmp), removed when the object dies.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::string& path() const { return path_; }
    std::string file(const std::string& name) const { return path_ + "/" + name; }

private:
    std::string path_;
};

struct RunResult {
    int exit_code = -1;  // the process's exit status; 128 + signal when killed
    std::string out;     // stdout
    std::string err;     // stderr
    double seconds = 0;       // wall-clock time of m3055
    double peak_rss_mib = 0;  // its peak resident memory (wait4's getrusage, support/measure_child.c)
    int killed_by = 0;        // the signal that ended m3055, or 0 when it exited
};

// Runs the built m3055 binary with `args` (no shell), capturing stdout and
// stderr, through support/measure_child.c, which measures it.
RunResult run_m3055(const std::vector<std::string>& args);

// The same, started in the background: signal() reaches m3055 (the launcher
// passes SIGINT, SIGTERM, SIGHUP and SIGBUS on), wait() collects the result.
class Running {
public:
    explicit Running(const std::vector<std::string>& args);
    ~Running();  // kills and reaps the process if wait() was not called
    Running(const Running&) = delete;
    Running& operator=(const Running&) = delete;
    void signal(int number) const;
    bool finished();  // without waiting
    // Waits (up to `seconds`) until the program has loaded Mesa's GL driver,
    // i.e. made its context (its SIGBUS handler and interrupt handling are in
    // place by then): tests that signal "inside the render" wait for this
    // instead of guessing a time, which a loaded or sanitized run may exceed.
    bool wait_for_gl_driver(double seconds = 60.0);
    RunResult wait();

private:
    TempDir capture_;
    int pid_ = -1;
    bool reaped_ = false;
    int status_ = 0;
};

// Every entry under `folder` (recursively, symlinks not followed), relative
// path -> its bytes for a regular file, "<fifo>", "<link> TARGET", "<folder>"...
// Equal snapshots before and after a run: nothing created, nothing left
// behind (no temporary), every file byte-identical.
// `except`: an entry (a folder: with all it holds) left out, e.g. the
// shader cache m3055 grade keeps in its output folder.
std::map<std::string, std::string> snapshot(const std::string& folder, const std::string& except = "");

// Writes `text` to `path` (throws on failure).
void write_text(const std::string& path, const std::string& text);
std::string read_text(const std::string& path);
bool file_exists(const std::string& path);

// Absolute path of `relative` in the repository.
std::string source_path(const std::string& relative);
// tests/data/reference-images/NAME: the three scenes rendered by an independent
// double-precision implementation (NAME.json, NAME.png, NAME.pfm; see the README there).
std::string reference_image_path(const std::string& name);

}  // namespace m3055::test
