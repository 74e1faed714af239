// Packs materials into the float records the generated GLSL unpacks
// (models/glsl_generator.cpp: fetch_material). A record is the model id, its
// family, the parameters in the model table's order (models/model_spec.h:
// gpu_floats_of), then the model's derived values; records are
// material_record_texels() RGBA32F texels apart.
#pragma once

#include "scene/scene.h"

#include <vector>

namespace m3055 {

// Texels per record: the largest model's record (models/model_table.h).
int material_record_texels();

// Appends one record (material_record_texels() * 4 floats) for `material`.
void pack_material(const Material& material, std::vector<float>& out);

}  // namespace m3055
