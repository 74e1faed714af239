// The material records (passes/material_buffer.h) as every pass that shades
// reads them: a buffer texture of RGBA32F texels on texture unit 0
// (u_materials), one record every material_record_texels() texels. The one
// upload for the frame, the BRDF grid and the stress harness.
#pragma once

#include "gl/gl_api.h"
#include "gl/gl_object.h"

#include <vector>

namespace m3055 {

class MaterialTexture {
public:
    explicit MaterialTexture(const GlApi& gl);

    // Uploads `records` (pack_material's floats, record after record) and
    // binds them as the buffer texture of unit 0, leaving unit 0 active.
    void upload(const std::vector<float>& records);

    // A program's material uniforms: the sampler's unit and the record
    // stride. Call after UseProgram.
    void set_uniforms(unsigned program) const;

private:
    const GlApi& gl_;
    GlBuffer buffer_;
    GlTexture texture_;
};

}  // namespace m3055
