// The A/B split's read-outs in the window: B's display readback,
// the count of pixels on another display level, and the third pane |A - B|
// as a GL texture. The numbers come from grading/ab_compare.h
// (tested there and against headless renders); this keeps them between
// renders and recomputes them only after one (or when the scale changes).
#pragma once

#include "grading/ab_compare.h"
#include "explore/explorer.h"
#include "gl/gl_api.h"
#include "gl/gl_object.h"
#include "frame/renderer.h"

#include <optional>
#include <string>

namespace m3055::explore {

class CompareView {
public:
    explicit CompareView(const GlApi& gl) : gl_(gl) {}
    CompareView(const CompareView&) = delete;
    CompareView& operator=(const CompareView&) = delete;

    // After every render: B's readback and the difference are stale.
    void invalidate() { fresh_ = false; }

    // Brings the read-outs up to date with A's display and renderer B (the
    // split is on); the difference pane only when the view asks for it.
    void update(const Explorer& explorer, const Rgb8Image& a, Renderer& b);

    const grading::LevelDifference& difference() const { return difference_; }
    unsigned texture() const { return texture_.id(); }
    int scale_used() const { return scale_used_; }
    const Rgb8Image& difference_image() const { return image_; }
    const Rgb8Image& b_display() const { return b_display_; }  // B as shown, this render
    // "|A - B| x 4 (auto)": the pane's label.
    std::string scale_label(const View& view) const;
    // "123 of 163840 pixels (0.08 %) on another level": the count's line.
    std::string count_label() const;
    // "123 px on another level": short enough for one line above the pane.
    std::string pane_count_label() const;

private:
    const GlApi& gl_;
    bool fresh_ = false;
    Rgb8Image b_display_, image_;
    grading::LevelDifference difference_;
    int scale_used_ = 1;
    int scale_asked_ = -1;  // the view's diff_scale when image_ was made
    GlTexture texture_;  // the |A - B| pane
};

}  // namespace m3055::explore
