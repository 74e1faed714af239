#include "explore/state.h"

#include "io/message_text.h"
#include "models/model_table.h"

#include <algorithm>

namespace m3055::explore {

Material* selected_material(ExplorerState& state) {
    if (state.scene.objects.empty()) return nullptr;
    state.selected_object =
        std::clamp(state.selected_object, 0, static_cast<int>(state.scene.objects.size()) - 1);
    return &state.scene.objects[state.selected_object].material;
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

Scene compare_scene(const ExplorerState& state) {
    Scene b = state.scene;
    if (!b.objects.empty()) {
        const int i = std::clamp(state.selected_object, 0, static_cast<int>(b.objects.size()) - 1);
        b.objects[i].material = state.material_b;
    }
    return b;
}

}  // namespace m3055::explore
