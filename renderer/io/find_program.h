// Where a helper program (gnuplot) is on $PATH, as a shell would find it,
// without running a shell.
#pragma once

#include <string>

namespace m3055 {

// The first executable `name` in a directory of $PATH (an empty entry is the
// current directory; no $PATH: /usr/bin:/bin), or "" when there is none.
std::string find_program(const std::string& name);

}  // namespace m3055
