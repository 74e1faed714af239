// How the explorer draws its displays: A shows the scene, B (in the A/B
// split) the compare scene, each with a Renderer of its own. The rule that
// keeps edits from stalling on a shader compile lives here, so `m3055 bench
// --latency` times the explorer's own rule: a scene needing a specialization
// not compiled yet is drawn at once with the general program (the same
// pixels, byte for byte), and drawn again with the specialized one once the
// explorer has been idle for kIdleBeforeCompile. No GL calls here beyond
// the Renderer's; the caller waits for the GPU (glFinish) as it needs.
#pragma once

#include "explore/explorer.h"
#include "frame/renderer.h"

#include <cstddef>

namespace m3055::explore {

// Seconds without input before a waiting specialized program is compiled.
inline constexpr double kIdleBeforeCompile = 0.12;
// Seconds without input before a preview of area lights is drawn again with the render's samples.
inline constexpr double kIdleBeforeRefine = 0.12;

// Draws with the general program while a specialization waits, and compiles
// the general programs now (start-up), so that no later render compiles.
void defer_compiles(Renderer& renderer);

// A frame of the preview should take at most this (slider to pixels).
inline constexpr double kPreviewBudgetMs = 35.0;
inline constexpr int kMaxPreviewDivisor = 8;

// How much smaller than the display a preview of area lights is drawn
// (Renderer::render_reduced): from the last preview's time, the smallest
// divisor whose frame fits kPreviewBudgetMs, taking a frame's cost as
// proportional to its pixels.
class PreviewScale {
public:
    int divisor() const;
    // A preview drawn at `divisor` took `ms` (GPU finished).
    void note(double ms, int divisor);

private:
    double full_size_ms_ = 0.0;  // the estimated cost of a preview at the display's size
};

// A's scene, and B's compare scene when the split is on. A scene with area
// lights (preview_differs) is drawn as a preview: the area lights' fast
// sampling (kFastSampling: one or two points and one shadow ray an emitter,
// docs/lights.md), at 1/divisor of the display's size.
void render_displays(const Explorer& explorer, Renderer& a, Renderer& b, int divisor = 1);

// Whether the last render_displays drew a preview that differs from what
// `m3055 render` draws (a scene with area or sky lights): then the display
// is "refining" until refine_when_idle has drawn it again.
bool preview_differs(const Scene& scene);

// After kIdleBeforeRefine s of no input: A (and B in the split) drawn again
// with the render's sampling (kRenderSampling), its specialized program built
// if it waits: the display's pixels are then the render's, byte for byte.
void refine_displays(const Explorer& explorer, Renderer& a, Renderer& b);
// The same for `region` only: the explorer refines in tiles between frames
// (explore/refine_tiles.h), so input waits for one tile at most; tiles over
// the whole display give refine_displays's pixels. With kFastSampling: the
// preview's pixels at the display's size (a preview drawn smaller, sharpened
// first: about 1 s for the softbox, where the render's take 12 s and more).
void refine_region(const Explorer& explorer, Renderer& a, Renderer& b, const DisplayRegion& region,
                   AreaSampling sampling = kRenderSampling);
// A tile of refinement should take about this long (input waits for one tile at most).
inline constexpr double kRefineBandMs = 60.0;
// While refining, a frame shows the tiles drawn so far this often (a frame a
// tile cost 12 of 57 s of the sky fill's refine).
inline constexpr double kRefineFrameSeconds = 0.25;

// Specialized programs waiting to be compiled, on A and B together.
std::size_t deferred_programs(const Renderer& a, const Renderer& b);

// After kIdleBeforeCompile s of no input: the first display with a program
// waiting (A, then B) drawn again with its specialized program (the same
// pixels); later frames use it. Returns whether it drew.
bool render_specialized_when_idle(const Explorer& explorer, Renderer& a, Renderer& b);

}  // namespace m3055::explore
