#include "passes/material_texture.h"

#include "passes/material_buffer.h"

namespace m3055 {

MaterialTexture::MaterialTexture(const GlApi& gl) : gl_(gl), buffer_(gl), texture_(gl) {}

void MaterialTexture::upload(const std::vector<float>& records) {
    // A scene without objects still gets one (zero) record: a buffer texture
    // over an empty buffer is not something to hand a driver.
    static const std::vector<float> zero_record(std::size_t(material_record_texels()) * 4, 0.0f);
    const std::vector<float>& data = records.empty() ? zero_record : records;
    gl_.BindBuffer(GL_TEXTURE_BUFFER, buffer_.id());
    gl_.BufferData(GL_TEXTURE_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_STREAM_DRAW);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.BindTexture(GL_TEXTURE_BUFFER, texture_.id());
    gl_.TexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, buffer_.id());
}

void MaterialTexture::set_uniforms(unsigned program) const {
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_materials"), 0);
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_material_texels"), material_record_texels());
}

}  // namespace m3055
