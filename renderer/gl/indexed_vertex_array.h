// A vertex array object with its vertex and index buffers, made and deleted
// together; the index buffer is recorded in the VAO. Shared by the mesh pass
// and the benchmark's UV spheres.
#pragma once

#include "gl/gl_api.h"
#include "gl/gl_object.h"

#include <cstddef>

namespace m3055 {

class IndexedVertexArray {
public:
    explicit IndexedVertexArray(const GlApi& gl);

    // Binds the VAO and the vertex buffer (for VertexAttribPointer set-up).
    void bind() const;
    // Replaces both buffers' contents (usage: GL_STATIC_DRAW, GL_STREAM_DRAW), leaving the VAO bound.
    void upload(const void* vertices, std::size_t vertex_bytes, const void* indices, std::size_t index_bytes,
                unsigned usage) const;
    unsigned vao() const { return vao_.id(); }

private:
    const GlApi& gl_;
    GlVertexArray vao_;
    GlBuffer vertex_buffer_, index_buffer_;
};

}  // namespace m3055
