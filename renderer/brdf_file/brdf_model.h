// A .brdf file as an entry of the model table (family brdf), registered at run
// time: its parameters are the entry's (number, colour, flag, with the file's
// ranges and defaults) plus the tangent `axis` of the classic models, and its
// code is the entry's GLSL (brdf_glsl.h). Entries are never removed
// (models/model_table.h), so loading a file again after an edit adds a new
// entry; loading an unchanged file returns the entry it already has.
#pragma once

#include "brdf_file/brdf_file.h"
#include "io/input_path.h"
#include "models/material.h"

#include <string>
#include <string_view>

namespace m3055 {

struct ModelSpec;

struct BrdfModel {
    const ModelSpec* spec = nullptr;
    BrdfFile file;
    std::string path;  // where load_brdf_model read it (InputPath::path)
    // The table parameter holding the file's parameter `name` ("" if none).
    std::string field(std::string_view name) const;
};

// Reads and parses `path` and returns its table entry (added if the file is
// new or changed). Throws BrdfError ("FILE:LINE: problem"). Call from the
// thread that renders (models/model_table.h).
const BrdfModel& load_brdf_model(const std::string& path);
// The same for a file opened at `file.path`, its messages naming `file.shown`.
const BrdfModel& load_brdf_model(const io::InputPath& file);

// The file behind a table entry; nullptr for a built-in model.
const BrdfModel* find_brdf_model(const ModelSpec& spec);

// The explorer's reload: `current`'s model from `path` again, keeping the value
// of each parameter whose name and kind are unchanged (clamped into a changed
// range) and the axis; others take the file's defaults. A parse error throws
// BrdfError with the file's line; GLSL errors surface when the program is built
// (ShaderError naming FILE:LINE), so a caller keeps `current` until a render
// with the result succeeds.
Material reload_brdf_material(const Material& current, const std::string& path);

// A file's entry whose GLSL failed to compile: left out of the general
// programs from now on (ModelTable::retire), so the other models keep drawing.
void retire_brdf_model(const ModelSpec& spec);

}  // namespace m3055
