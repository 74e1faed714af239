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

// Draws with the general program while a specialization waits, and compiles
// the general programs now (start-up), so that no later render compiles.
void defer_compiles(Renderer& renderer);

// A's scene, and B's compare scene when the split is on.
void render_displays(const Explorer& explorer, Renderer& a, Renderer& b);

// Specialized programs waiting to be compiled, on A and B together.
std::size_t deferred_programs(const Renderer& a, const Renderer& b);

// After kIdleBeforeCompile s of no input: the first display with a program
// waiting (A, then B) drawn again with its specialized program (the same
// pixels); later frames use it. Returns whether it drew.
bool render_specialized_when_idle(const Explorer& explorer, Renderer& a, Renderer& b);

}  // namespace m3055::explore
