#include "gl/context.h"

#include "gl/context_egl.h"
#include "gl/context_osmesa.h"

#include <cstdlib>

namespace m3055 {

Backend parse_backend(const std::string& name) {
    if (name == "auto") return Backend::automatic;
    if (name == "egl") return Backend::egl;
    if (name == "osmesa") return Backend::osmesa;
    throw std::invalid_argument("unknown backend \"" + name + "\" (expected auto, egl or osmesa)");
}

static std::string env_or(const char* name, const char* fallback) {
    const char* value = std::getenv(name);
    return value && *value ? value : fallback;
}

std::string egl_library_name() { return env_or("M3055_EGL_LIBRARY", "libEGL.so.1"); }
std::string osmesa_library_name() { return env_or("M3055_OSMESA_LIBRARY", "libOSMesa.so.8"); }

std::string HeadlessContext::renderer_string() const {
    const GLubyte* text = gl_.GetString(GL_RENDERER);
    return text ? reinterpret_cast<const char*>(text) : "unknown";
}

std::unique_ptr<HeadlessContext> HeadlessContext::create(Backend backend) {
    std::string reasons;
    auto note = [&](const std::string& why) { reasons += (reasons.empty() ? "" : "; ") + why; };

    if (backend == Backend::automatic || backend == Backend::egl) {
        std::string why;
        if (auto context = create_egl_context(&why)) return context;
        note(why);
    }
    if (backend == Backend::automatic || backend == Backend::osmesa) {
        std::string why;
        if (auto context = create_osmesa_context(&why)) return context;
        note(why);
    }
    const char* install =
        backend == Backend::egl      ? "install libegl1 and libgl1-mesa-dri"
        : backend == Backend::osmesa ? "install libosmesa6"
                                     : "install libegl1 and libgl1-mesa-dri (EGL) or libosmesa6 (OSMesa)";
    throw ContextError("no OpenGL 3.3 core context: " + reasons + " (" + install + ")");
}

}  // namespace m3055
