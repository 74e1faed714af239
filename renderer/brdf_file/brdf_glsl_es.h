// A .brdf file's shader block, written in desktop GLSL, translated to GLSL ES
// 3.00 (WebGL2). Desktop GLSL (4.20 §4.1.10, "Implicit
// Conversions") converts int -> float, int -> uint and uint -> float (and
// their vectors) where an operator, an initializer, an assignment, a return
// or a function's argument needs it; GLSL ES 3.00 has no implicit conversion
// at all (ES 3.00 §4.1.10), so `max(x, 0)`, `pow(x, 2)`, `float a = 1;`,
// `x * 2`, `return 1;` and `x > 0` are errors there.
//
// The translator parses the block (declarations, statements, expressions with
// GLSL's precedence), types every expression from the declarations it has
// seen (the file's globals, functions, structs and locals, plus `globals`: the
// parameters the wrapper declares) and from the built-in functions' signatures,
// and inserts the conversion exactly where the desktop compiler applies one:
// an int literal becomes `2.0` (`2u` for uint), any other int expression
// `float(...)` / `vecN(...)`. Nothing else changes, and no line is added or
// removed, so a compiler message's line is still the .brdf's own.
//
// Where the type of an operand is not known (an undeclared name, a macro, a
// call that no signature matches), nothing is converted around it: the ES
// compiler's error then names the .brdf line. A syntax error stops the
// translation there; the conversions before it are kept.
//
// A function the block defines under a built-in's name (BRDF Explorer's
// d_phong.brdf defines its own `reflect`) hides the built-in on the desktop;
// GLSL ES forbids redefining a built-in (ES 3.00 §6.1), so such names are
// reported for the wrapper to rename with a #define (brdf_glsl.cpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace m3055 {

struct GlslEsTranslation {
    std::string text;                             // the block, as GLSL ES (same lines)
    int conversions = 0;                          // implicit conversions made explicit
    std::vector<std::string> redefined_builtins;  // functions defined under a built-in's name
    std::string stopped;                          // "" or "line N: why" where parsing stopped
};

// `globals`: (type, name) of names the block uses without declaring them,
// e.g. {"float", "roughness"}, {"vec3", "baseColor"}, {"bool", "isotropic"}.
GlslEsTranslation translate_glsl_es(const std::string& block,
                                    const std::vector<std::pair<std::string, std::string>>& globals);

}  // namespace m3055
