// Whole-process timing: spawn the m3055 executable itself, wait, take the wall time.
#pragma once

#include <string>
#include <vector>

namespace m3055::bench {

// The running executable's path (/proc/self/exe).
std::string self_executable();

// Runs `argv` (argv[0] = program path) with `extra_env` ("NAME=value") added to
// this process's environment, stdout and stderr to /dev/null. Returns the wall
// time in milliseconds; throws std::runtime_error if it does not exit 0.
double run_process_ms(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env = {});

}  // namespace m3055::bench
