// Small helpers shared by the tests: temporary folders and running the m3055
// executable as a separate process (to check exit codes, stderr and files).
#pragma once

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
};

// Runs the built m3055 binary with `args` (no shell), capturing stdout and stderr.
RunResult run_m3055(const std::vector<std::string>& args);

// Writes `text` to `path` (throws on failure).
void write_text(const std::string& path, const std::string& text);
std::string read_text(const std::string& path);
bool file_exists(const std::string& path);

// Absolute paths of the repository and of ../shared.
std::string source_path(const std::string& relative);
std::string shared_path(const std::string& relative);

}  // namespace m3055::test
