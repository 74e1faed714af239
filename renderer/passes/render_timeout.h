// A render passed its deadline (Renderer::set_deadline, checked between
// chunks of bounded work: passes/draw_chunks.h); the image is unfinished.
#pragma once

#include <stdexcept>

namespace m3055 {

class RenderTimeout : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace m3055
