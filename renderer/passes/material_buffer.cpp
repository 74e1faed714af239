#include "passes/material_buffer.h"

#include "models/model_table.h"

namespace m3055 {

int material_record_texels() { return model_table().record_texels(); }

void pack_material(const Material& material, std::vector<float>& out) {
    const ModelSpec& spec = material.model();
    const std::size_t base = out.size();
    out.resize(base + std::size_t(material_record_texels()) * 4, 0.0f);
    float* record = out.data() + base;
    record[0] = float(spec.id);
    record[1] = float(static_cast<int>(spec.family));
    // The parameters' values are laid out as their floats (lobes: count, then
    // (w, m) pairs), so the record is the values rounded to float.
    const std::vector<double>& values = material.values();
    for (std::size_t i = 0; i < values.size(); ++i) record[2 + i] = float(values[i]);
    float* derived = record + 2 + values.size();
    for (const DerivedValue& value : spec.derived) {
        value.fill(material, derived);
        derived += value.floats;
    }
}

}  // namespace m3055
