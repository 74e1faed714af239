// The display's read-outs in the window: the pixel probe under the mouse, the
// level histogram, click-to-pick and the selection's outline. The numbers
// come from renderer/analysis/pixel_probe.h (tested there and against
// headless renders); this draws them and keeps the readbacks they need, taken
// lazily after a render (a slider drag pays for none of them).
#pragma once

#include "analysis/pixel_probe.h"
#include "explore/display_view.h"
#include "explore/state.h"
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
    }

    // The display pixel under window point (mx, my) when A is drawn at `shown` (ImGui units).
    static std::optional<std::pair<int, int>> pixel_at(const Scene& scene, const Rect& shown, float mx, float my);

    PixelProbe probe(const ExplorerState& state, Renderer& renderer, int x, int y);
    // A's display as read back (PNG values, rows top to bottom): what the A/B difference uses.
    const Rgb8Image& display_image(Renderer& renderer) { return display(renderer); }
    // The scanline profile of state.profile_row, from the same readback as the
    // probe; nullptr before any row was hovered.
    const RowProfile* profile(const ExplorerState& state, Renderer& renderer);
    // Selects the object under pixel (x, y); false (selection kept) on the background.
    bool pick(ExplorerState& state, int x, int y);
    const LevelHistogram& histogram(const ExplorerState& state, Renderer& renderer);
    // The selected object's outline over A, around it (its own pixels stay as
    // rendered); computes the object ids when `allowed_to_compute` (not during a drag).
    void draw_outline(const ExplorerState& state, const Rect& shown, bool allowed_to_compute);

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
};

}  // namespace m3055::explore
