// The words of the GLSL that brdf_glsl_es.h translates: its tokens, its types
// and the built-in functions' signatures, as far as a conversion depends on them.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

namespace m3055::glsl_es {

struct Token {
    enum Kind { identifier, int_literal, uint_literal, float_literal, punct, end } kind = end;
    std::size_t begin = 0, end_offset = 0;
    std::string text;
    int line = 1;
    bool decimal = false;  // an int literal written in decimal (not hex, not octal): "2" -> "2.0"
};

// The block's tokens, without comments and preprocessor lines (GLSL 4.20 §3.3:
// a '#' first on its line starts a directive, continued by a backslash), and an
// end token. `macros` gets the names the block #defines: their types are not known.
std::vector<Token> tokenize(const std::string& s, std::set<std::string>& macros);

struct Type {
    enum Base { unknown, void_type, boolean, integer, uinteger, floating, structure, opaque } base = unknown;
    int size = 1;        // vector components, or a matrix's columns
    int rows = 1;        // a matrix's rows (1: not a matrix)
    int array = 0;       // 0: not an array; -1: size not known; else its size
    std::string name;    // a struct's

    bool known() const { return base != unknown; }
    bool numeric_int() const { return array == 0 && rows == 1 && (base == integer || base == uinteger); }
    bool numeric_float() const { return array == 0 && base == floating; }
    bool scalar() const { return array == 0 && size == 1 && rows == 1; }
    bool operator==(const Type& o) const {
        return base == o.base && size == o.size && rows == o.rows && array == o.array && name == o.name;
    }
    bool operator!=(const Type& o) const { return !(*this == o); }
};

Type basic(Type::Base base, int size = 1, int rows = 1);
Type element_of(Type t);  // an array's element
Type builtin_type(const std::string& word);  // a built-in type's name -> its type; unknown for other words
bool is_qualifier(const std::string& word);  // const, in, out, highp, ...

// How a built-in types its result and which arguments take floats
// (GLSL 4.20 §8; genType: float or vecN).
enum class Builtin {
    component_float,   // float only, component-wise: result the widest argument (sin, pow, mix, step ...)
    component_number,  // float, int and uint versions (abs sign min max clamp): converts only a mixed call
    scalar_float,      // length distance dot: float
    like_first,        // normalize reflect refract faceforward: the first argument's type
    cross,             // vec3
    compare_vectors,   // lessThan ... notEqual: bvecN
    any_all,           // bool
    not_vector,        // not: bvecN
    bool_of_float,     // isnan isinf: bool / bvecN
    matrix_same,       // inverse matrixCompMult
    transpose,
    determinant,
};

// The built-in functions by name.
const std::map<std::string, Builtin>& builtins();

}  // namespace m3055::glsl_es
