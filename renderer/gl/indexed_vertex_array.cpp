#include "gl/indexed_vertex_array.h"

namespace m3055 {

IndexedVertexArray::IndexedVertexArray(const GlApi& gl) : gl_(gl) {
    gl_.GenVertexArrays(1, &vao_);
    gl_.GenBuffers(1, &vertex_buffer_);
    gl_.GenBuffers(1, &index_buffer_);
    gl_.BindVertexArray(vao_);
    gl_.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, index_buffer_);  // recorded in the VAO
    gl_.BindVertexArray(0);
}

IndexedVertexArray::~IndexedVertexArray() {
    gl_.DeleteVertexArrays(1, &vao_);
    const unsigned buffers[] = {vertex_buffer_, index_buffer_};
    gl_.DeleteBuffers(2, buffers);
}

void IndexedVertexArray::bind() const {
    gl_.BindVertexArray(vao_);
    gl_.BindBuffer(GL_ARRAY_BUFFER, vertex_buffer_);
}

void IndexedVertexArray::upload(const void* vertices, std::size_t vertex_bytes, const void* indices,
                                std::size_t index_bytes, unsigned usage) const {
    bind();
    gl_.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertex_bytes), vertices, usage);
    gl_.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(index_bytes), indices, usage);
}

}  // namespace m3055
