#include "explore/readouts.h"

namespace m3055::explore {

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

const NonFiniteView& Readouts::nonfinite(const ExplorerState& state, Renderer& renderer) {
    if (!nonfinite_) {
        if (may_render_nonfinite(state.scene)) {
            if (!raw_) raw_ = renderer.read_raw();
            nonfinite_ = nonfinite_view(*raw_);
        } else {
            nonfinite_ = NonFiniteView{};
        }
    }
    return *nonfinite_;
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

const std::vector<int>* Readouts::object_ids(const Scene& scene, bool allowed_to_compute) {
    if (ids_.empty()) {
        if (!allowed_to_compute || scene.objects.size() < 2) return nullptr;
        ids_ = picker(scene).object_ids();
    }
    return &ids_;
}

}  // namespace m3055::explore
