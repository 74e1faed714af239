#include "explore/explorer.h"

#include "io/message_text.h"
#include "models/model_table.h"

#include <algorithm>

namespace m3055::explore {

Material* selected_material(Explorer& explorer) { return material_of(explorer.doc, explorer.view.selected_object); }

Scene compare_scene(const Explorer& explorer) {
    Scene b = explorer.doc.scene;
    if (!b.objects.empty()) {
        const int i = std::clamp(explorer.view.selected_object, 0, static_cast<int>(b.objects.size()) - 1);
        b.objects[std::size_t(i)].material = explorer.doc.material_b;
    }
    return b;
}

std::vector<const ModelSpec*> all_models() {
    std::vector<const ModelSpec*> models;
    for (const ModelSpec& model : model_table().models()) models.push_back(&model);
    return models;
}

std::string valid_light_name(const std::string& typed) {
    std::string kept;
    for (char c : typed)
        if (static_cast<unsigned char>(c) >= 0x20 && c != 0x7F) kept += c;
    if (kept.size() > 64) kept.resize(64);
    while (!kept.empty() && !text::is_valid_utf8(kept)) kept.pop_back();  // a cut multi-byte character
    return kept;
}

}  // namespace m3055::explore
