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

PixelProbe Readouts::probe(const Explorer& e, Renderer& renderer, int x, int y) {
    if (!raw_) raw_ = renderer.read_raw();
    const Scene& scene = e.doc.scene;
    return probe_pixel(scene, picker(scene), *raw_, display(renderer), x, y, e.view.plotted_light);
}

const NonFiniteView& Readouts::nonfinite(const Scene& scene, Renderer& renderer) {
    if (!nonfinite_) {
        if (may_render_nonfinite(scene)) {
            if (!raw_) raw_ = renderer.read_raw();
            nonfinite_ = nonfinite_view(*raw_);
        } else {
            nonfinite_ = NonFiniteView{};
        }
    }
    return *nonfinite_;
}

const RowProfile* Readouts::profile(const Display& shown, int row, Renderer& renderer) {
    if (row < 0 || row >= shown.height) return nullptr;  // none yet, or the display shrank
    if (!profile_ || profile_->row != row) {
        const Rgb8Image& image = display(renderer);
        if (row >= image.height) return nullptr;  // the scene's display not drawn at its size yet
        profile_ = row_profile(image, shown.bits, row);
    }
    return &*profile_;
}

int Readouts::pick(const Scene& scene, int x, int y) { return picker(scene).pick(x, y).object; }

const LevelHistogram& Readouts::histogram(const Display& shown, Renderer& renderer) {
    if (!histogram_fresh_) histogram_ = level_histogram(display(renderer), shown.bits);
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
