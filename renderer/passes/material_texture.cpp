#include "passes/material_texture.h"

#include "models/glsl_generator.h"
#include "passes/material_buffer.h"
#include "passes/render_targets.h"

#include <stdexcept>
#include <string>

namespace m3055 {

MaterialTexture::MaterialTexture(const GlApi& gl) : gl_(gl), texture_(gl) {}

void MaterialTexture::upload(const std::vector<float>& records) {
    // A scene without objects still gets one (zero) record, so that the
    // texture is never empty.
    static const std::vector<float> zero_record(std::size_t(material_record_texels()) * 4, 0.0f);
    const std::vector<float>& data = records.empty() ? zero_record : records;
    const std::size_t texels = data.size() / 4, width = std::size_t(kMaterialTextureWidth);
    const std::size_t full_rows = texels / width, rest = texels % width;
    const int rows = int(full_rows + (rest ? 1 : 0));
    gl_.ActiveTexture(GL_TEXTURE0);
    if (rows > rows_) {
        GLint max_size = 0;
        gl_.GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
        if (rows > max_size)
            throw std::runtime_error("the material records need " + std::to_string(rows) + " rows of " +
                                     std::to_string(width) + " texels; GL_MAX_TEXTURE_SIZE is " +
                                     std::to_string(max_size));
        define_texture_2d(gl_, texture_, kRgba32f, kMaterialTextureWidth, rows, nullptr);
        rows_ = rows;
    }
    gl_.BindTexture(GL_TEXTURE_2D, texture_.id());
    // The whole rows, then what is left of the last one: rows past it keep
    // older records, which no index reaches.
    if (full_rows)
        gl_.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kMaterialTextureWidth, GLsizei(full_rows), GL_RGBA, GL_FLOAT,
                          data.data());
    if (rest)
        gl_.TexSubImage2D(GL_TEXTURE_2D, 0, 0, GLint(full_rows), GLsizei(rest), 1, GL_RGBA, GL_FLOAT,
                          data.data() + full_rows * width * 4);
}

void MaterialTexture::set_uniforms(unsigned program) const {
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_materials"), 0);
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_material_texels"), material_record_texels());
}

}  // namespace m3055
