// Packs materials into the float records glsl/common/material.glsl reads
// (MATERIAL_TEXELS RGBA32F texels per object).
#pragma once

#include "scene/scene.h"

#include <vector>

namespace m3055 {

// Texels 0-4: the paper's models; 5-10: the classic models (SPEC 5).
inline constexpr int kMaterialTexels = 11;

// Appends one record (kMaterialTexels * 4 floats) for `material` to `out`.
void pack_material(const Material& material, std::vector<float>& out);

}  // namespace m3055
