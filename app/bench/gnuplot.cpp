// Runs gnuplot (Debian: gnuplot-nox) on bench.gp, as a separate process.
#include "plot.h"

#include "image/image.h"
#include "io/find_program.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace m3055::bench {

namespace fs = std::filesystem;

std::string find_gnuplot() { return find_program("gnuplot"); }

int run_gnuplot(const std::string& gnuplot, const std::string& script, const std::string& out,
                const std::string& log) {
    // A single-quoted gnuplot string: a quote in the path is written twice.
    std::string quoted_out;
    for (const char c : out) quoted_out += c == '\'' ? std::string("''") : std::string(1, c);
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("bench: fork failed");
    if (pid == 0) {
        const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0) _exit(127);
        dup2(fd, 1);
        dup2(fd, 2);
        std::string program = gnuplot, e = "-e", set_out = "out='" + quoted_out + "'", file = script;
        char* argv[] = {program.data(), e.data(), set_out.data(), file.data(), nullptr};
        execv(program.c_str(), argv);
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string first_line(const std::string& path) {
    std::ifstream file(path);
    std::string line;
    while (std::getline(file, line))
        if (line.find_first_not_of(" \t^") != std::string::npos) return line;
    return "(no message)";
}

PlotOutcome write_plot(const std::string& dir, const std::vector<PlotPoint>& points, const std::string& title) {
    const std::string script = gnuplot_script(points, title);
    write_file_atomic((fs::path(dir) / "bench.gp").string(), script.data(), script.size());
    const std::string gnuplot = find_gnuplot();
    if (gnuplot.empty()) return PlotOutcome::no_gnuplot;

    // gnuplot writes its output as it goes: draw into a temporary name, then rename.
    const std::string partial = ".bench.png." + std::to_string(getpid()) + ".partial";
    const fs::path partial_path = fs::path(dir) / partial, log = fs::path(dir) / (partial + ".log");
    const int status =
        run_gnuplot(gnuplot, (fs::path(dir) / "bench.gp").string(), partial_path.string(), log.string());
    const std::string message = status == 0 ? "" : first_line(log.string());
    std::error_code ignored;
    fs::remove(log, ignored);
    if (status != 0 || !fs::is_regular_file(partial_path) || fs::file_size(partial_path, ignored) == 0) {
        fs::remove(partial_path, ignored);
        throw std::runtime_error("bench: gnuplot failed on " + (fs::path(dir) / "bench.gp").string() +
                                 " (status " + std::to_string(status) + "): " + message);
    }
    fs::rename(partial_path, fs::path(dir) / "bench.png");
    return PlotOutcome::drawn;
}

}  // namespace m3055::bench
