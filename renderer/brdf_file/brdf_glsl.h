// The GLSL that puts a .brdf file's shader block into the renderer's programs.
// The block is written for a program of its own (BRDF Explorer's), so its
// top-level names (BRDF, helpers such as sqr, constants such as PI) would
// collide with the renderer's and with other files'. Each of them is renamed
// by a #define to m3055_b<ID>_n<name> around the block (and #undef'd after),
// the parameters become globals of the file's names set from the material
// record before BRDF is called, and the block itself is included as its own
// source string starting at the .brdf's line, so a compile error names the
// .brdf file and its own line number.
#pragma once

#include "brdf_file/brdf_file.h"

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace m3055 {

// The names the block declares at file scope ("TYPE NAME" outside braces and
// parentheses: functions, constants, structs), and those it #defines.
struct BrdfTopLevel {
    std::set<std::string> declared;
    std::set<std::string> macros;
};
BrdfTopLevel brdf_top_level_names(const std::string& shader);

// The sources of model `id` (its table entry's glsl_sources): the wrapper,
// named `wrapper_path`, defining `hook` (Material mat, vec3 L, V, N, X, Y),
// and the block, whose messages name file.name. `field(i)` is the Material
// field of parameter i.
std::vector<std::pair<std::string, std::string>> brdf_glsl_sources(const BrdfFile& file, int id,
                                                                   const std::string& wrapper_path,
                                                                   const std::string& hook,
                                                                   const std::vector<std::string>& fields);

// The same for GLSL ES 3.00 (WebGL2; ModelSpec::glsl_sources_es): the block
// with desktop GLSL's implicit conversions made explicit, line for line
// (brdf_glsl_es.h), and the functions it defines under a built-in's name
// renamed like its other top-level names.
std::vector<std::pair<std::string, std::string>> brdf_glsl_es_sources(const BrdfFile& file, int id,
                                                                      const std::string& wrapper_path,
                                                                      const std::string& hook,
                                                                      const std::vector<std::string>& fields);

}  // namespace m3055
