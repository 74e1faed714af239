#include "explore_ui/compare_view.h"

#include "explore_ui/display_view.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace m3055::explore {

void CompareView::update(const Explorer& explorer, const Rgb8Image& a, Renderer& b) {
    const View& view = explorer.view;
    if (!fresh_) {
        b_display_ = b.read_display();
        difference_ = grading::level_difference(a, b_display_, explorer.doc.scene.display.bits);
        scale_asked_ = -1;  // the pane too
        fresh_ = true;
    }
    if (!view.compare_diff || scale_asked_ == view.diff_scale) return;
    scale_asked_ = view.diff_scale;
    scale_used_ = view.diff_scale > 0 ? view.diff_scale : grading::auto_difference_scale(a, b_display_);
    image_ = grading::scaled_difference(a, b_display_, scale_used_);
    upload_pane_texture(gl_, texture_, image_);
}

std::string CompareView::scale_label(const View& view) const {
    char text[96];
    std::snprintf(text, sizeof text, "|A - B| x %d (%s)", scale_used_, view.diff_scale > 0 ? "chosen" : "auto");
    return text;
}

std::string CompareView::count_label() const {
    char text[128];
    std::snprintf(text, sizeof text, "%llu of %llu pixels (%.2f %%) on another display level",
                  static_cast<unsigned long long>(difference_.differing),
                  static_cast<unsigned long long>(difference_.pixels), 100.0 * difference_.share());
    return text;
}

std::string CompareView::pane_count_label() const {
    return std::to_string(difference_.differing) + " px on another level";
}

}  // namespace m3055::explore
