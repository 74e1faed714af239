// BRDF Explorer's `.brdf` files (Disney, github.com/wdas/brdf), as its
// BRDFAnalytic reader takes them: a first line "analytic", "#" comment lines,
// a parameter block
//   ::begin parameters
//   float NAME MIN MAX DEFAULT | color NAME R G B | bool NAME DEFAULT
//   ::end parameters
// and a shader block (::begin shader ... ::end shader) of desktop GLSL that
// defines vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y). The parameters
// are globals of the same names in that GLSL (BRDF Explorer's uniforms).
// Parsing is pure text work (no GL): a GLSL compile error is found later, when
// the program is built, and named by the .brdf's own line (brdf_glsl.h).
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace m3055 {

// what(): one line "FILE:LINE: problem" (or "FILE: problem").
class BrdfError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct BrdfParam {
    enum class Kind { number, colour, flag };
    Kind kind = Kind::number;
    std::string name;                 // as in the file (baseColor): the GLSL global and the scene key
    double min = 0.0, max = 1.0;      // number
    std::vector<double> fallback;     // 1 value (number, flag 0/1) or 3 (colour)
    int line = 0;                     // in the file, 1-based
};

struct BrdfFile {
    std::string name;                 // the file name as messages show it
    std::vector<BrdfParam> params;
    std::string shader;               // the shader block, lines as in the file ("\n" ends)
    int shader_line = 0;              // the file's line of the shader block's first line
    const BrdfParam* find(std::string_view param) const;
};

// Parses `text`; `name` prefixes every message. Throws BrdfError.
BrdfFile parse_brdf(std::string_view text, const std::string& name);

// True for a GLSL keyword, reserved word or built-in function name, and for
// the names the renderer gives the file's code (BRDF, its arguments L V N X Y,
// the renderer's macros): a parameter may not be called so.
bool is_reserved_brdf_name(const std::string& name);
// Only the GLSL keywords, reserved words and built-in functions.
bool is_glsl_reserved(const std::string& name);

}  // namespace m3055
