#include "explore/explorer.h"

#include "io/message_text.h"
#include "models/model_table.h"

#include <algorithm>

namespace m3055::explore {

Material* selected_material(Explorer& explorer) {
    Material* own = material_of(explorer.doc, explorer.view.selected_object);
    const int group = selected_group(explorer);
    if (group < 0) return own;
    explorer.view.selected_group = group;
    return &explorer.doc.scene.objects[std::size_t(explorer.view.selected_object)].groups[std::size_t(group)].material;
}

bool work_unsaved(const Explorer& explorer) {
    return unsaved(explorer.doc) || !explorer.session.replaced_unsaved.empty();
}

int selected_group(const Explorer& explorer) {
    const auto& objects = explorer.doc.scene.objects;
    if (objects.empty()) return -1;
    const int i = std::clamp(explorer.view.selected_object, 0, static_cast<int>(objects.size()) - 1);
    const int groups = static_cast<int>(objects[std::size_t(i)].groups.size());
    return groups == 0 ? -1 : std::clamp(explorer.view.selected_group, 0, groups - 1);
}

Scene compare_scene(const Explorer& explorer) {
    Scene b = explorer.doc.scene;
    if (!b.objects.empty()) {
        const int i = std::clamp(explorer.view.selected_object, 0, static_cast<int>(b.objects.size()) - 1);
        Object& object = b.objects[std::size_t(i)];
        const int group = selected_group(explorer);
        if (group >= 0) object.groups[std::size_t(group)].material = explorer.doc.material_b;
        if (group <= 0) object.material = explorer.doc.material_b;
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
