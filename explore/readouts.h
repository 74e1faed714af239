// The display's read-outs: the pixel probe, the level histogram, the scanline
// profile, click-to-pick and the object ids the selection's outline is drawn
// from. The numbers come from renderer/analysis/pixel_probe.h (tested there
// and against headless renders); this keeps the readbacks they need, taken
// lazily after a render (a slider drag pays for none of them). No ImGui:
// explore_ui draws them.
#pragma once

#include "analysis/pixel_probe.h"
#include "explore/nonfinite_view.h"
#include "explore/explorer.h"
#include "frame/renderer.h"

#include <memory>
#include <optional>

namespace m3055::explore {

class Readouts {
public:
    // After every render of A: the readbacks and the picker are stale.
    void invalidate() {
        display_.reset();
        raw_.reset();
        picker_.reset();
        ids_.clear();
        histogram_fresh_ = false;
        profile_.reset();
        nonfinite_.reset();
    }

    // The probe; a pixel whose value is NaN or infinite says so (PixelProbe::text).
    PixelProbe probe(const Explorer& explorer, Renderer& renderer, int x, int y);
    // A's NaN and infinite pixels: read back once a render, and only for a
    // scene that can hold them (a .brdf material); none for the others.
    const NonFiniteView& nonfinite(const Scene& scene, Renderer& renderer);
    // A's display as read back (PNG values, rows top to bottom): what the A/B difference uses.
    const Rgb8Image& display_image(Renderer& renderer) { return display(renderer); }
    // The scanline profile of display row `row`, from the same readback as the
    // probe; nullptr before any row was hovered (row -1).
    const RowProfile* profile(const Display& display, int row, Renderer& renderer);
    // The object under pixel (x, y); -1 on the background.
    int pick(const Scene& scene, int x, int y);
    const LevelHistogram& histogram(const Display& display, Renderer& renderer);
    // The object under each display pixel (rows top to bottom), for the
    // selection's outline; computed when `allowed_to_compute` (not during a
    // drag), else nullptr until it was. Also nullptr with one object: nothing
    // to tell apart.
    const std::vector<int>* object_ids(const Scene& scene, bool allowed_to_compute);

private:
    const Rgb8Image& display(Renderer& renderer);
    const ScenePicker& picker(const Scene& scene);
    std::optional<Rgb8Image> display_;
    std::optional<RgbFloatImage> raw_;
    std::unique_ptr<ScenePicker> picker_;
    std::vector<int> ids_;  // object per pixel, for the outline
    LevelHistogram histogram_;
    bool histogram_fresh_ = false;
    std::optional<RowProfile> profile_;
    std::optional<NonFiniteView> nonfinite_;
};

}  // namespace m3055::explore
