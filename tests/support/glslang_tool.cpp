#include "glslang_tool.h"

#include "test_support.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fcntl.h>
#include <sstream>

namespace m3055::test {

std::string find_in_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::istringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
        if (access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return "";
}

ToolRun run_glslang(const std::vector<std::string>& args) {
    const std::string tool = find_in_path("glslangValidator");
    if (tool.empty()) {
        ADD_FAILURE() << "glslangValidator not found on PATH: install glslang-tools "
                         "(apt-get install glslang-tools; scripts/setup --for-tests installs it)";
        return {};
    }
    TempDir capture;
    const std::string log = capture.file("log");
    const pid_t pid = fork();
    if (pid < 0) {
        ADD_FAILURE() << "fork failed";
        return {};
    }
    if (pid == 0) {
        const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0) _exit(127);
        dup2(fd, 1);
        dup2(fd, 2);
        std::vector<std::string> copy = args;
        std::vector<char*> argv{const_cast<char*>(tool.c_str())};
        for (auto& a : copy) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(tool.c_str(), argv.data());
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    ToolRun run;
    run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    run.output = test::read_text(log);
    return run;
}

}  // namespace m3055::test
