// A program that does not compile or link: a broken build or driver, never an
// input file. what() is the GL log, several lines, each naming glsl/FILE:LINE;
// the commands print it whole (other errors are one line, io/message_text.h).
#pragma once

#include <stdexcept>

namespace m3055 {

class ShaderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace m3055
