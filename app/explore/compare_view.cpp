#include "explore/compare_view.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace m3055::explore {

CompareView::~CompareView() {
    if (texture_) gl_.DeleteTextures(1, &texture_);
}

void CompareView::update(const ExplorerState& state, const Rgb8Image& a, Renderer& b) {
    if (!fresh_) {
        b_display_ = b.read_display();
        difference_ = grading::level_difference(a, b_display_, state.scene.display.bits);
        scale_asked_ = -1;  // the pane too
        fresh_ = true;
    }
    if (!state.compare_diff || scale_asked_ == state.diff_scale) return;
    scale_asked_ = state.diff_scale;
    scale_used_ = state.diff_scale > 0 ? state.diff_scale : grading::auto_difference_scale(a, b_display_);
    image_ = grading::scaled_difference(a, b_display_, scale_used_);
    upload();
}

// Nearest-neighbour, like the display textures: each dot stays a block of whole pixels.
void CompareView::upload() {
    if (!texture_) gl_.GenTextures(1, &texture_);
    gl_.BindTexture(GL_TEXTURE_2D, texture_);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Rows go in bottom to top, as the renderer's display textures store them
    // (draw_display flips v for all panes alike).
    const std::size_t stride = std::size_t(image_.width) * 3;
    std::vector<std::uint8_t> rows(image_.pixels.size());
    for (int y = 0; y < image_.height; ++y)
        std::copy_n(image_.pixels.data() + std::size_t(image_.height - 1 - y) * stride, stride,
                    rows.data() + std::size_t(y) * stride);
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, image_.width, image_.height, 0, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    gl_.BindTexture(GL_TEXTURE_2D, 0);
}

std::string CompareView::scale_label(const ExplorerState& state) const {
    char text[96];
    std::snprintf(text, sizeof text, "|A - B| x %d (%s)", scale_used_,
                  state.diff_scale > 0 ? "chosen" : "auto");
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
