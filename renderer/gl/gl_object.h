// A GL object owned by one C++ value: deleted when the value goes, through
// the GlApi of the context that made it (GL functions are resolved per
// context, gl_api.h). Move-only, so an object has one owner and is deleted
// once. The context must be current when a handle is made or destroyed.
#pragma once

#include "gl/gl_api.h"

#include <utility>

namespace m3055 {

template <class Kind>
class GlObject {
public:
    GlObject() = default;  // holds nothing
    // A new object of this kind (Kind::make: glGen*).
    explicit GlObject(const GlApi& gl) : gl_(&gl), id_(Kind::make(gl)) {}
    // Takes ownership of `id`, made elsewhere (a program from build_program).
    GlObject(const GlApi& gl, unsigned id) : gl_(&gl), id_(id) {}
    ~GlObject() { reset(); }
    GlObject(GlObject&& other) noexcept : gl_(other.gl_), id_(std::exchange(other.id_, 0u)) {}
    GlObject& operator=(GlObject&& other) noexcept {
        if (this != &other) {
            reset();
            gl_ = other.gl_;
            id_ = std::exchange(other.id_, 0u);
        }
        return *this;
    }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;

    unsigned id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    // Deletes the object now; the handle then holds nothing.
    void reset() {
        if (id_) Kind::destroy(*gl_, id_);
        id_ = 0;
    }

private:
    const GlApi* gl_ = nullptr;
    unsigned id_ = 0;
};

namespace gl_kind {
struct Texture {
    static unsigned make(const GlApi& gl) {
        unsigned id = 0;
        gl.GenTextures(1, &id);
        return id;
    }
    static void destroy(const GlApi& gl, unsigned id) { gl.DeleteTextures(1, &id); }
};
struct Buffer {
    static unsigned make(const GlApi& gl) {
        unsigned id = 0;
        gl.GenBuffers(1, &id);
        return id;
    }
    static void destroy(const GlApi& gl, unsigned id) { gl.DeleteBuffers(1, &id); }
};
struct Framebuffer {
    static unsigned make(const GlApi& gl) {
        unsigned id = 0;
        gl.GenFramebuffers(1, &id);
        return id;
    }
    static void destroy(const GlApi& gl, unsigned id) { gl.DeleteFramebuffers(1, &id); }
};
struct VertexArray {
    static unsigned make(const GlApi& gl) {
        unsigned id = 0;
        gl.GenVertexArrays(1, &id);
        return id;
    }
    static void destroy(const GlApi& gl, unsigned id) { gl.DeleteVertexArrays(1, &id); }
};
struct Query {
    static unsigned make(const GlApi& gl) {
        unsigned id = 0;
        gl.GenQueries(1, &id);
        return id;
    }
    static void destroy(const GlApi& gl, unsigned id) { gl.DeleteQueries(1, &id); }
};
// Programs are made by build_program (gl/program.h) and adopted: no make.
struct Program {
    static void destroy(const GlApi& gl, unsigned id) { gl.DeleteProgram(id); }
};
}  // namespace gl_kind

using GlTexture = GlObject<gl_kind::Texture>;
using GlBuffer = GlObject<gl_kind::Buffer>;
using GlFramebuffer = GlObject<gl_kind::Framebuffer>;
using GlVertexArray = GlObject<gl_kind::VertexArray>;
using GlProgram = GlObject<gl_kind::Program>;
using GlQuery = GlObject<gl_kind::Query>;

}  // namespace m3055
