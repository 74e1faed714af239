#include "gl/indexed_vertex_array.h"

namespace m3055 {

IndexedVertexArray::IndexedVertexArray(const GlApi& gl)
    : gl_(gl), vao_(gl), vertex_buffer_(gl), index_buffer_(gl) {
    gl_.BindVertexArray(vao_.id());
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_.id());  // recorded in the VAO
    gl_.BindVertexArray(0);
}

void IndexedVertexArray::bind() const {
    gl_.BindVertexArray(vao_.id());
    gl_.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer_.id());
}

void IndexedVertexArray::upload(const void* vertices, std::size_t vertex_bytes, const void* indices,
                                std::size_t index_bytes, unsigned usage) const {
    bind();
    gl_.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertex_bytes), vertices, usage);
    gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(index_bytes), indices, usage);
}

}  // namespace m3055
