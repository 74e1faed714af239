#include "brdf_file/brdf_file.h"

#include "io/message_text.h"

#include <cmath>
#include <cstdlib>
#include <regex>
#include <set>
#include <sstream>

namespace m3055 {

namespace {

// The most parameters a file may declare (each is a slot of the material record).
constexpr std::size_t kMaxBrdfParams = 64;

std::string trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r\f\v");
    if (first == std::string_view::npos) return std::string();
    const auto last = s.find_last_not_of(" \t\r\f\v");
    return std::string(s.substr(first, last - first + 1));
}

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string word; in >> word;) out.push_back(word);
    return out;
}

class Parser {
public:
    Parser(std::string_view text, const std::string& name) : text_(text) { out_.name = name; }

    BrdfFile run() {
        enum class State { header, outside, parameters, shader } state = State::header;
        bool had_parameters = false, had_shader = false;
        int block_line = 0;
        std::size_t pos = 0;
        while (pos < text_.size()) {
            const std::size_t end = std::min(text_.find('\n', pos), text_.size());
            std::string line(text_.substr(pos, end - pos));
            pos = end + 1;
            ++line_;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            if (line.find('\0') != std::string::npos) fail("a NUL byte (not a text file)");
            const std::string t = trim(line);
            if (state == State::shader) {
                if (t == "::end shader") { state = State::outside; continue; }
                out_.shader += line + "\n";
                continue;
            }
            if (t.empty() || t[0] == '#') continue;
            if (state == State::header) {
                if (t != "analytic") fail("the first line must be \"analytic\", got " + text::quote(t));
                state = State::outside;
            } else if (state == State::parameters) {
                if (t == "::end parameters") state = State::outside;
                else parameter(t);
            } else if (t == "::begin parameters" || t == "::begin shader") {
                const bool shader = t == "::begin shader";
                bool& had = shader ? had_shader : had_parameters;
                if (had) fail("a second \"" + t + "\" block");
                had = true;
                block_line = line_;
                state = shader ? State::shader : State::parameters;
                if (shader) out_.shader_line = line_ + 1;
            } else {
                fail("expected \"::begin parameters\" or \"::begin shader\", got " + text::quote(t));
            }
        }
        if (state == State::header) fail_at(0, "empty: the first line must be \"analytic\"");
        if (state == State::parameters || state == State::shader)
            fail_at(block_line, std::string("the block is not closed by \"::end ") +
                                    (state == State::shader ? "shader" : "parameters") + "\"");
        if (!had_shader) fail_at(0, "no \"::begin shader\" block");
        require_brdf_function();
        return std::move(out_);
    }

private:
    [[noreturn]] void fail(const std::string& problem) const { fail_at(line_, problem); }
    [[noreturn]] void fail_at(int line, const std::string& problem) const {
        throw BrdfError(out_.name + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + problem);
    }

    double number(const std::string& word, const std::string& what) const {
        char* end = nullptr;
        const double value = std::strtod(word.c_str(), &end);
        if (word.empty() || *end != '\0' || !std::isfinite(value))
            fail(what + " must be a finite number, got " + text::quote(word));
        return value;
    }

    void parameter(const std::string& line) {
        std::string body = line.substr(0, line.find('#'));  // a trailing comment
        if (const auto slash = body.find("//"); slash != std::string::npos) body.resize(slash);
        const std::vector<std::string> w = words(body);
        if (w.empty()) return;
        BrdfParam p;
        p.line = line_;
        const std::string& type = w[0];
        const std::size_t wanted = type == "bool" ? 3 : 5;
        if (type != "float" && type != "color" && type != "bool")
            fail("a parameter line is \"float NAME MIN MAX DEFAULT\", \"color NAME R G B\" or \"bool NAME DEFAULT\", "
                 "got " + text::quote(trim(body)));
        if (w.size() != wanted)
            fail("\"" + type + "\" needs " + std::to_string(wanted - 1) + " fields after it, got " +
                 std::to_string(w.size() - 1) + " in " + text::quote(trim(body)));
        p.name = w[1];
        check_name(p.name);
        if (type == "float") {
            p.min = number(w[2], p.name + ": MIN");
            p.max = number(w[3], p.name + ": MAX");
            p.fallback = {number(w[4], p.name + ": DEFAULT")};
            if (!(p.min <= p.max)) fail(p.name + ": MIN " + w[2] + " is above MAX " + w[3]);
            if (p.fallback[0] < p.min || p.fallback[0] > p.max)
                fail(p.name + ": DEFAULT " + w[4] + " is outside [" + w[2] + ", " + w[3] + "]");
        } else if (type == "color") {
            p.kind = BrdfParam::Kind::colour;
            for (int i = 0; i < 3; ++i) {
                p.fallback.push_back(number(w[2 + std::size_t(i)], p.name + ": " + "RGB"[i]));
                if (p.fallback.back() < 0.0 || p.fallback.back() > 1.0)
                    fail(p.name + ": a colour component must be in [0, 1], got " + w[2 + std::size_t(i)]);
            }
        } else {
            p.kind = BrdfParam::Kind::flag;
            const std::string& v = w[2];
            if (v != "0" && v != "1" && v != "true" && v != "false")
                fail(p.name + ": a bool's DEFAULT is 0, 1, true or false, got " + text::quote(v));
            p.fallback = {v == "1" || v == "true" ? 1.0 : 0.0};
        }
        if (out_.params.size() == kMaxBrdfParams)
            fail("more than " + std::to_string(kMaxBrdfParams) + " parameters");
        out_.params.push_back(std::move(p));
    }

    void check_name(const std::string& name) const {
        static const std::regex identifier("[A-Za-z_][A-Za-z0-9_]{0,63}");
        if (!std::regex_match(name, identifier))
            fail("parameter name " + text::quote(name) + " is not a GLSL identifier (letters, digits, _; at most 64)");
        if (is_reserved_brdf_name(name))
            fail("parameter name \"" + name + "\" is a GLSL keyword or built-in, or a name the renderer uses");
        if (out_.find(name)) fail("parameter \"" + name + "\" declared twice");
    }

    // The code without comments must define vec3 BRDF(...): BRDF Explorer calls it.
    void require_brdf_function() const {
        static const std::regex comments(R"(//[^\n]*|/\*[\s\S]*?\*/)");
        static const std::regex brdf(R"((^|[^A-Za-z0-9_])vec3\s+BRDF\s*\()");
        const std::string code = std::regex_replace(out_.shader, comments, " ");
        if (!std::regex_search(code, brdf))
            fail_at(out_.shader_line - 1, "the shader block defines no \"vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)\"");
    }

    std::string_view text_;
    BrdfFile out_;
    int line_ = 0;
};

}  // namespace

const BrdfParam* BrdfFile::find(std::string_view param) const {
    for (const BrdfParam& p : params)
        if (p.name == param) return &p;
    return nullptr;
}

BrdfFile parse_brdf(std::string_view text, const std::string& name) { return Parser(text, name).run(); }

bool is_glsl_reserved(const std::string& name) {
    // GLSL 4.50 keywords and reserved words, the built-in types and the
    // built-in functions a BRDF is likely to call; then the renderer's names.
    static const std::set<std::string> reserved = [] {
        std::set<std::string> out;
        std::istringstream in(
            "attribute const uniform varying buffer shared coherent volatile restrict readonly writeonly atomic_uint "
            "layout centroid flat smooth noperspective patch sample break continue do for while switch case default "
            "if else subroutine in out inout float double int void bool true false invariant precise discard return "
            "mat2 mat3 mat4 dmat2 dmat3 dmat4 mat2x2 mat2x3 mat2x4 mat3x2 mat3x3 mat3x4 mat4x2 mat4x3 mat4x4 "
            "vec2 vec3 vec4 ivec2 ivec3 ivec4 bvec2 bvec3 bvec4 dvec2 dvec3 dvec4 uint uvec2 uvec3 uvec4 "
            "lowp mediump highp precision sampler1D sampler2D sampler3D samplerCube samplerBuffer struct "
            "common partition active asm class union enum typedef template this resource goto inline noinline "
            "public static extern external interface long short half fixed unsigned superp input output "
            "hvec2 hvec3 hvec4 fvec2 fvec3 fvec4 sampler3DRect filter sizeof cast namespace using "
            "radians degrees sin cos tan asin acos atan sinh cosh tanh asinh acosh atanh pow exp log exp2 log2 "
            "sqrt inversesqrt abs sign floor trunc round roundEven ceil fract mod modf min max clamp mix step "
            "smoothstep isnan isinf length distance dot cross normalize faceforward reflect refract "
            "matrixCompMult transpose determinant inverse lessThan greaterThan equal notEqual any all not "
            "texture texelFetch fma frexp ldexp main");
        for (std::string word; in >> word;) out.insert(word);
        return out;
    }();
    return reserved.count(name) || name.rfind("gl_", 0) == 0 || name.find("__") != std::string::npos;
}

bool is_reserved_brdf_name(const std::string& name) {
    if (is_glsl_reserved(name)) return true;
    // BRDF and its arguments, the wrapper's own names (brdf_glsl.cpp), the renderer's prefixes: uniforms, generated code, its macros.
    for (const char* prefix : {"u_", "m3055_", "M3055_", "HAS_", "MODEL_", "FAMILY_", "LIGHT_", "MAX_"})
        if (name.rfind(prefix, 0) == 0) return true;
    for (const char* own : {"BRDF", "L", "V", "N", "X", "Y", "Material", "mat", "PI", "SPECIALIZED"})
        if (name == own) return true;
    return false;
}

}  // namespace m3055
