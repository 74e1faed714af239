// What `compare` and `grade` accept as an image: a PNG, a PFM, or a scene
// (rendered first). Chosen by the name's extension, so an input's meaning
// never depends on its bytes.
#pragma once

#include "grading/level_compare.h"
#include "frame/renderer.h"
#include "io/input_path.h"
#include "scene/scene.h"

#include <string>

namespace m3055::grading {

enum class InputKind { png, pfm, scene };
// ".png" and ".pfm" (any case) are images; anything else is a scene file.
InputKind input_kind(const std::string& path);

// Reads a PNG or PFM as levels of a `bits`-bit display. Throws (ImageError,
// io::InputError) with one line naming the file; a path that is not a regular
// file is refused before it is opened (a FIFO would block the read).
LevelImage read_level_image(const std::string& path, int bits);
// The same for a file opened at `file.path`, every message naming `file.shown`.
LevelImage read_level_image(const io::InputPath& file, int bits);

// Renders `scene` with `renderer` (its deadline, if any, applies) and returns
// the display's levels and, with `linear`, the linear colour (a second
// read-back, of floats: grading does without it).
LevelImage render_levels(Renderer& renderer, const Scene& scene, bool linear = true);

}  // namespace m3055::grading
