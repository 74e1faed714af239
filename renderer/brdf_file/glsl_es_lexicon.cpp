#include "brdf_file/glsl_es_lexicon.h"

#include <algorithm>
#include <cctype>

namespace m3055::glsl_es {

namespace {

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

}  // namespace

// ---- tokens -----------------------------------------------------------------------

std::vector<Token> tokenize(const std::string& s, std::set<std::string>& macros) {
    static const char* const operators[] = {"<<=", ">>=", "++", "--", "<<", ">>", "<=", ">=", "==", "!=", "&&",
                                            "||",  "^^",  "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^="};
    std::vector<Token> out;
    int line = 1;
    bool line_start = true;
    std::size_t i = 0;
    while (i < s.size()) {
        const char c = s[i];
        if (c == '\n') {
            ++line, ++i, line_start = true;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (s.compare(i, 2, "//") == 0) {
            while (i < s.size() && s[i] != '\n') ++i;
        } else if (s.compare(i, 2, "/*") == 0) {
            const std::size_t stop = std::min(s.find("*/", i + 2), s.size());
            line += int(std::count(s.begin() + std::ptrdiff_t(i), s.begin() + std::ptrdiff_t(stop), '\n'));
            i = std::min(stop + 2, s.size());
        } else if (c == '#' && line_start) {
            std::size_t j = i + 1;
            while (j < s.size() && (s[j] == ' ' || s[j] == '\t')) ++j;
            if (s.compare(j, 6, "define") == 0) {
                j += 6;
                while (j < s.size() && (s[j] == ' ' || s[j] == '\t')) ++j;
                std::size_t k = j;
                while (k < s.size() && ident_char(s[k])) ++k;
                if (k > j) macros.insert(s.substr(j, k - j));
            }
            while (i < s.size() && s[i] != '\n') {
                if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == '\n') ++line, ++i;
                ++i;
            }
        } else {
            line_start = false;
            Token t;
            t.begin = i;
            t.line = line;
            if (ident_start(c)) {
                while (i < s.size() && ident_char(s[i])) ++i;
                t.kind = Token::identifier;
            } else if (digit(c) || (c == '.' && i + 1 < s.size() && digit(s[i + 1]))) {
                bool is_float = false;
                if (c == '0' && i + 1 < s.size() && (s[i + 1] == 'x' || s[i + 1] == 'X')) {
                    i += 2;
                    while (i < s.size() && std::isxdigit(static_cast<unsigned char>(s[i]))) ++i;
                } else {
                    while (i < s.size() && digit(s[i])) ++i;
                    if (i < s.size() && s[i] == '.') {
                        is_float = true;
                        ++i;
                        while (i < s.size() && digit(s[i])) ++i;
                    }
                    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
                        std::size_t j = i + 1;
                        if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
                        if (j < s.size() && digit(s[j])) {
                            is_float = true;
                            i = j;
                            while (i < s.size() && digit(s[i])) ++i;
                        }
                    }
                }
                t.kind = is_float ? Token::float_literal : Token::int_literal;
                if (i < s.size() && (s[i] == 'f' || s[i] == 'F')) {
                    t.kind = Token::float_literal;
                    ++i;
                } else if (i + 1 < s.size() && (s.compare(i, 2, "lf") == 0 || s.compare(i, 2, "LF") == 0)) {
                    t.kind = Token::float_literal;
                    i += 2;
                } else if (!is_float && i < s.size() && (s[i] == 'u' || s[i] == 'U')) {
                    t.kind = Token::uint_literal;
                    ++i;
                }
                const std::string digits = s.substr(t.begin, i - t.begin);
                t.decimal = t.kind == Token::int_literal && (digits == "0" || digits[0] != '0');
            } else {
                t.kind = Token::punct;
                std::size_t length = 1;
                for (const char* op : operators)
                    if (s.compare(i, std::char_traits<char>::length(op), op) == 0) {
                        length = std::char_traits<char>::length(op);
                        break;
                    }
                i += length;
            }
            t.end_offset = i;
            t.text = s.substr(t.begin, i - t.begin);
            out.push_back(t);
        }
    }
    Token end;
    end.begin = end.end_offset = s.size();
    end.line = line;
    out.push_back(end);
    return out;
}

// ---- types ------------------------------------------------------------------------

Type basic(Type::Base base, int size, int rows) {
    Type t;
    t.base = base, t.size = size, t.rows = rows;
    return t;
}

Type element_of(Type t) {
    t.array = 0;
    return t;
}

// A built-in type's name -> its type; unknown for other words.
Type builtin_type(const std::string& w) {
    if (w == "float") return basic(Type::floating);
    if (w == "int") return basic(Type::integer);
    if (w == "uint") return basic(Type::uinteger);
    if (w == "bool") return basic(Type::boolean);
    if (w == "void") return basic(Type::void_type);
    auto vector = [&](const std::string& prefix, Type::Base base) -> Type {
        if (w.size() == prefix.size() + 1 && w.rfind(prefix, 0) == 0 && w.back() >= '2' && w.back() <= '4')
            return basic(base, w.back() - '0');
        return Type();
    };
    for (const auto& [prefix, base] : {std::pair<const char*, Type::Base>{"vec", Type::floating},
                                       {"ivec", Type::integer}, {"uvec", Type::uinteger}, {"bvec", Type::boolean}}) {
        const Type t = vector(prefix, base);
        if (t.known()) return t;
    }
    if (w.rfind("mat", 0) == 0) {
        if (w.size() == 4 && w[3] >= '2' && w[3] <= '4') return basic(Type::floating, w[3] - '0', w[3] - '0');
        if (w.size() == 6 && w[4] == 'x' && w[3] >= '2' && w[3] <= '4' && w[5] >= '2' && w[5] <= '4')
            return basic(Type::floating, w[3] - '0', w[5] - '0');
    }
    if (w.find("sampler") != std::string::npos || w.find("image") != std::string::npos) return basic(Type::opaque);
    return Type();
}

bool is_qualifier(const std::string& w) {
    static const std::set<std::string> words = {"const", "uniform", "in", "out", "inout", "highp", "mediump", "lowp",
                                                "flat", "smooth", "centroid", "invariant", "precise", "noperspective"};
    return words.count(w) > 0;
}

// ---- built-in functions -------------------------------------------------------------

const std::map<std::string, Builtin>& builtins() {
    static const std::map<std::string, Builtin> table = [] {
        std::map<std::string, Builtin> t;
        for (const char* f : {"radians", "degrees", "sin",   "cos",      "tan",  "asin",  "acos",        "atan",
                              "sinh",    "cosh",    "tanh",  "asinh",    "acosh", "atanh", "pow",        "exp",
                              "log",     "exp2",    "log2",  "sqrt",     "inversesqrt", "floor", "trunc", "round",
                              "roundEven", "ceil",  "fract", "mod",      "mix",  "step",  "smoothstep", "fma"})
            t[f] = Builtin::component_float;
        for (const char* f : {"abs", "sign", "min", "max", "clamp"}) t[f] = Builtin::component_number;
        for (const char* f : {"length", "distance", "dot"}) t[f] = Builtin::scalar_float;
        for (const char* f : {"normalize", "reflect", "refract", "faceforward"}) t[f] = Builtin::like_first;
        t["cross"] = Builtin::cross;
        for (const char* f : {"lessThan", "lessThanEqual", "greaterThan", "greaterThanEqual", "equal", "notEqual"})
            t[f] = Builtin::compare_vectors;
        t["any"] = t["all"] = Builtin::any_all;
        t["not"] = Builtin::not_vector;
        t["isnan"] = t["isinf"] = Builtin::bool_of_float;
        t["inverse"] = t["matrixCompMult"] = Builtin::matrix_same;
        t["transpose"] = Builtin::transpose;
        t["determinant"] = Builtin::determinant;
        return t;
    }();
    return table;
}

}  // namespace m3055::glsl_es
