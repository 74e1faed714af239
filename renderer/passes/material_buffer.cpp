#include "passes/material_buffer.h"

namespace m3055 {

// The model ids glsl/common/material.glsl defines (MODEL_*).
static float model_id(Model model) {
    switch (model) {
        case Model::highlight: return 0;
        case Model::translucent: return 1;
        case Model::metal: return 2;
        case Model::metal_blinn: return 3;
        case Model::metal_phong: return 4;
    }
    return 0;
}

void pack_material(const Material& material, std::vector<float>& out) {
    const float record[kMaterialTexels * 4] = {
        float(material.color.r), float(material.color.g), float(material.color.b), model_id(material.model),
        float(material.d), float(material.w), float(material.m), float(material.t_n),
        float(material.t_p), float(material.lobes.size()), 0.0f, 0.0f,
        0, 0, 0, 0,
        0, 0, 0, 0,
    };
    const std::size_t base = out.size();
    out.insert(out.end(), record, record + kMaterialTexels * 4);
    for (std::size_t j = 0; j < material.lobes.size() && j < std::size_t(kMaxLobes); ++j) {
        out[base + 12 + 2 * j] = float(material.lobes[j].w);
        out[base + 13 + 2 * j] = float(material.lobes[j].m);
    }
}

}  // namespace m3055
