#include "headless_context.h"

#include "interrupt.h"
#include "progress.h"

#include "gl/shader_cache.h"

#include <iostream>

namespace m3055 {

std::unique_ptr<HeadlessContext> make_headless_context(Backend backend) {
    const std::string note = disable_shader_cache_if_unusable();
    if (!note.empty()) std::cerr << error_line(note) << "\n";
    report_bus_errors(mesa_shader_cache_folder());
    return HeadlessContext::create(backend);
}

}  // namespace m3055
