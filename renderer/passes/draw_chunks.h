// Draws split into chunks of bounded work, so that a render with a deadline
// (Renderer::set_deadline) can stop between them: a legal
// scene of 100 000 overlapping screen-filling translucent spheres under 16
// spot lights would take hours in one draw call on llvmpipe.
#pragma once

#include "gl/gl_api.h"
#include "passes/display_region.h"
#include "passes/render_timeout.h"

#include <chrono>
#include <cstddef>
#include <algorithm>
#include <optional>
#include <utility>
#include <stdexcept>
#include <vector>

namespace m3055 {

// Estimated work, in shaded pixel-lights: a fragment shaded under L lights
// costs 1 + L. A chunk holds at most kChunkWork: the slowest shading measured
// here (translucent spheres under 16 spot lights, llvmpipe, 2 cores) does
// about 6e7 a second, so a chunk takes well under 0.1 s and the deadline is
// overshot by about that much.
inline constexpr double kChunkWork = 4.0e6;
// Set-up work of one triangle or one sphere quad, beyond its pixels.
inline constexpr double kPrimitiveWork = 64.0;

// A contiguous range of elements (sphere instances, or mesh indices), its
// estimated work, and the rows of the display it can cover, [row0, row1)
// counted from the bottom as GL does.
struct DrawSpan {
    std::size_t first = 0, count = 0;
    double work = 0;
    int row0 = 0, row1 = 0;
};

// Groups `spans` (in draw order, each starting where the previous ended) into
// chunks of at most `budget` work each; a span costlier than that on its own
// is cut into equal parts whose counts are multiples of `granule` (3 for
// triangle indices). The chunks cover the same elements in the same order, so
// drawing them one by one gives the same pixels as one draw of all.
std::vector<DrawSpan> plan_chunks(const std::vector<DrawSpan>& spans, double budget, std::size_t granule);

// A chunk that is still over `budget` (one sphere covering the screen, a few
// large triangles) is drawn in horizontal bands of rows, each with a scissor:
// every pixel lies in one band, where it sees the same draws in the same
// order, so the pixels are the same. Returns the bands' first rows and the
// end row ({row0, row1} when one band is enough).
std::vector<int> band_rows(const DrawSpan& chunk, double budget);

// Draws planned chunks in order, an oversized one in scissored bands of rows;
// between two draws it waits for the GPU and checks the deadline, or, with no
// deadline, only flushes (llvmpipe then rasterizes and frees what it holds for
// the draws so far, without this thread waiting).
class ChunkedDraws {
public:
    using Deadline = std::optional<std::chrono::steady_clock::time_point>;
    ChunkedDraws(const GlApi& gl, const Deadline& deadline, int width, int height)
        : gl_(gl), deadline_(deadline), width_(width), height_(height) {}

    // Throws RenderTimeout once the deadline has passed.
    void check_deadline() const;

    // A span of `count` elements (`primitives` triangles or quads) whose pixels
    // lie in the NDC rectangle `rect` {x0, y0, x1, y1} (nullptr: anywhere),
    // shaded under `lights` lights.
    DrawSpan span_of(std::size_t first, std::size_t count, std::size_t primitives, const float* rect,
                     std::size_t lights) const;

    // Only the box `region` of the frame is drawn (Renderer::render_region):
    // the caller has the scissor test on with that box; bands stay inside it.
    void clip_to(const DisplayRegion& region) { clip_ = region; }

    // draw(first, count) for each chunk (or band of one).
    template <class Draw>
    void run(const std::vector<DrawSpan>& chunks, const Draw& draw) {
        const ScissorAtExit restore{*this};  // also after a RenderTimeout
        bool first_draw = true;
        for (const DrawSpan& chunk : chunks) {
            const std::vector<int> rows = band_rows(chunk, kChunkWork);
            if (rows.size() > 2) gl_.Enable(GL_SCISSOR_TEST);
            for (std::size_t band = 0; band + 1 < rows.size(); ++band) {
                int row0 = rows[band], row1 = rows[band + 1];
                if (clip_) row0 = std::max(row0, clip_->y0), row1 = std::min(row1, clip_->y1);
                if (rows.size() > 2 && row1 <= row0) continue;  // a band outside the clip
                if (!first_draw) between_draws();
                first_draw = false;
                if (rows.size() > 2)
                    gl_.Scissor(clip_ ? clip_->x0 : 0, row0, clip_ ? clip_->x1 - clip_->x0 : width_, row1 - row0);
                draw(chunk.first, chunk.count);
            }
            if (rows.size() > 2) restore_scissor();
        }
    }

private:
    struct ScissorAtExit {
        const ChunkedDraws& draws;
        ~ScissorAtExit() { draws.restore_scissor(); }
    };
    // Off, or the clip's box.
    void restore_scissor() const {
        if (!clip_) return gl_.Disable(GL_SCISSOR_TEST);
        gl_.Enable(GL_SCISSOR_TEST);
        gl_.Scissor(clip_->x0, clip_->y0, clip_->x1 - clip_->x0, clip_->y1 - clip_->y0);
    }
    std::optional<DisplayRegion> clip_;
    void between_draws() const;
    const GlApi& gl_;
    const Deadline& deadline_;
    int width_, height_;
};

}  // namespace m3055
