// Headless OpenGL 3.3 core contexts: EGL (Mesa surfaceless, then EGL device),
// then OSMesa. The libraries are opened at run time, so a machine without one
// of them still runs the other, and a machine with neither gets one clear line
// naming what to install.
#pragma once

#include "gl/gl_api.h"

#include <memory>
#include <stdexcept>
#include <string>

namespace m3055 {

enum class Backend { automatic, egl, osmesa };

// Parses "auto", "egl" or "osmesa"; throws std::invalid_argument otherwise.
Backend parse_backend(const std::string& name);

class ContextError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class HeadlessContext {
public:
    virtual ~HeadlessContext() = default;

    // Creates a context and makes it current on this thread. `automatic` tries
    // EGL surfaceless, EGL device, then OSMesa. Throws ContextError with every
    // attempt's reason when none gives a 3.3 core context.
    static std::unique_ptr<HeadlessContext> create(Backend backend);

    const GlApi& gl() const { return gl_; }
    // "egl-surfaceless", "egl-device" or "osmesa".
    const std::string& backend_name() const { return backend_name_; }
    // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    std::string renderer_string() const;

protected:
    GlApi gl_;
    std::string backend_name_;
};

// Library names, overridable for tests of the failure paths:
// $M3055_EGL_LIBRARY (default libEGL.so.1), $M3055_OSMESA_LIBRARY (default libOSMesa.so.8).
std::string egl_library_name();
std::string osmesa_library_name();

}  // namespace m3055
