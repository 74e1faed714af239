#include "explore/readouts.h"

#include <imgui.h>

#include <cmath>

namespace m3055::explore {

std::optional<std::pair<int, int>> Readouts::pixel_at(const Scene& scene, const Rect& shown, float mx, float my) {
    if (shown.w <= 0 || shown.h <= 0) return std::nullopt;
    const int x = static_cast<int>(std::floor((mx - shown.x) / shown.w * scene.display.width));
    const int y = static_cast<int>(std::floor((my - shown.y) / shown.h * scene.display.height));
    if (x < 0 || y < 0 || x >= scene.display.width || y >= scene.display.height) return std::nullopt;
    return std::make_pair(x, y);
}

const Rgb8Image& Readouts::display(Renderer& renderer) {
    if (!display_) display_ = renderer.read_display();
    return *display_;
}

const ScenePicker& Readouts::picker(const Scene& scene) {
    if (!picker_) picker_ = std::make_unique<ScenePicker>(scene);
    return *picker_;
}

PixelProbe Readouts::probe(const ExplorerState& state, Renderer& renderer, int x, int y) {
    if (!raw_) raw_ = renderer.read_raw();
    return probe_pixel(state.scene, picker(state.scene), *raw_, display(renderer), x, y, state.plotted_light);
}

const RowProfile* Readouts::profile(const ExplorerState& state, Renderer& renderer) {
    const int row = state.profile_row;
    if (row < 0 || row >= state.scene.display.height) return nullptr;  // none yet, or the display shrank
    if (!profile_ || profile_->row != row) profile_ = row_profile(display(renderer), state.scene.display.bits, row);
    return &*profile_;
}

bool Readouts::pick(ExplorerState& state, int x, int y) {
    const int object = picker(state.scene).pick(x, y).object;
    if (object < 0) return false;
    state.selected_object = object;
    return true;
}

const LevelHistogram& Readouts::histogram(const ExplorerState& state, Renderer& renderer) {
    if (!histogram_fresh_) histogram_ = level_histogram(display(renderer), state.scene.display.bits);
    histogram_fresh_ = true;
    return histogram_;
}

void Readouts::draw_outline(const ExplorerState& state, const Rect& shown, bool allowed_to_compute) {
    const int w = state.scene.display.width, h = state.scene.display.height;
    if (ids_.empty()) {
        if (!allowed_to_compute || state.scene.objects.size() < 2) return;  // one object: nothing to tell apart
        ids_ = picker(state.scene).object_ids();
    }
    const float sx = shown.w / w, sy = shown.h / h;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const ImU32 colour = IM_COL32(255, 230, 0, 255);
    auto is_selected = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < w && y < h && ids_[std::size_t(y) * w + x] == state.selected_object;
    };
    // Around the selected pixels, on the neighbouring pixels' side: the
    // object's own pixels stay exactly as rendered.
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            if (is_selected(x, y)) continue;
            if (!(is_selected(x - 1, y) || is_selected(x + 1, y) || is_selected(x, y - 1) || is_selected(x, y + 1)))
                continue;
            const ImVec2 a(shown.x + x * sx, shown.y + y * sy);
            draw->AddRectFilled(a, ImVec2(a.x + sx, a.y + sy), colour);
        }
    }
}

}  // namespace m3055::explore
