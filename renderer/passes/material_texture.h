// The material records (passes/material_buffer.h) as every pass that shades
// reads them: a 2D texture of RGBA32F texels on texture unit 0 (u_materials),
// kMaterialTextureWidth texels a row, texel i at (i % width, i / width), one
// record every material_record_texels() texels (fetch_material in
// models/glsl_generator.cpp). A 2D texture rather than a buffer texture
// because WebGL2 has none; the floats, and so the pixels, are the same. The
// one upload for the frame, the BRDF grid and the stress harness.
#pragma once

#include "gl/gl_api.h"
#include "gl/gl_object.h"

#include <vector>

namespace m3055 {

class MaterialTexture {
public:
    explicit MaterialTexture(const GlApi& gl);

    // Uploads `records` (pack_material's floats, record after record) and
    // binds them as the 2D texture of unit 0, leaving unit 0 active. Throws
    // std::runtime_error when they need more rows than GL_MAX_TEXTURE_SIZE.
    void upload(const std::vector<float>& records);

    // A program's material uniforms: the sampler's unit and the record
    // stride. Call after UseProgram.
    void set_uniforms(unsigned program) const;

private:
    const GlApi& gl_;
    GlTexture texture_;
    int rows_ = 0;  // rows allocated: the texture is redefined only to grow
};

}  // namespace m3055
