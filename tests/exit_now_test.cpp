// app/exit_now.h: a finished `m3055 render` leaves its GL context to the
// operating system. Seen from outside: no thread of the process (llvmpipe's
// rasterizers, Mesa's queues) is joined before the process ends, and the
// output is whole, as with a normal exit.
#include "image/image.h"
#include "io/sanitized_build.h"
#include "test_paths.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace m3055::test {
namespace {

// The process's exit calls as strace -f writes them, one per line: "exit(0)"
// for a thread that ends, "exit_group(0)" for the process.
std::vector<std::string> exit_calls(const std::string& trace) {
    std::vector<std::string> calls;
    std::istringstream lines(trace);
    for (std::string line; std::getline(lines, line);) {
        const auto space = line.find(' ');  // after the thread id
        const auto close = line.find(')');
        if (space != std::string::npos && close != std::string::npos) {
            const auto call = line.find_first_not_of(' ', space);
            calls.push_back(line.substr(call, close + 1 - call));
        }
    }
    return calls;
}

TEST(ExitNow, RenderEndsWithoutJoiningItsThreads) {
    if (kSanitizedBuild) GTEST_SKIP() << "a sanitized build exits normally, for LeakSanitizer's check";
    if (std::system("strace -qq -o /dev/null true >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "strace cannot run here";
    TempDir dir;
    const std::string command = "strace -f -qq -e trace=exit,exit_group -o " + dir.file("trace") + " " +
                                M3055_BINARY + " render --scene " + source_path("scenes/spec_example.json") +
                                " --out " + dir.file("out.png") + " 2>" + dir.file("err");
    ASSERT_EQ(std::system(command.c_str()), 0) << read_text(dir.file("err"));
    EXPECT_EQ(exit_calls(read_text(dir.file("trace"))), std::vector<std::string>{"exit_group(0)"});
    const Rgb8Image png = read_png(dir.file("out.png"));
    EXPECT_EQ(png.width, 512);
    EXPECT_EQ(png.height, 320);
}

}  // namespace
}  // namespace m3055::test
