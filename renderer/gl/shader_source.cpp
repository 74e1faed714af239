#include "gl/shader_source.h"

#include "models/glsl_sources.h"
#include "models/glsl_generator.h"

#include <algorithm>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace m3055 {

namespace {
constexpr int kBrdfLineBase = 1000000;  // a .brdf file has fewer lines (1 MB at most)
}  // namespace

const char* find_glsl_source(const std::string& path) {
    for (const auto& source : glsl_sources())
        if (path == source.path) return source.text;
    return nullptr;
}

namespace {

// How messages name a source: glsl/FILE, generated/FILE, or a .brdf file's
// own name for its shader block ("brdf/ID/NAME", brdf_file/brdf_glsl.cpp).
std::string shown_name(const std::string& path) {
    if (path.rfind("generated/", 0) == 0) return path;
    if (path.rfind("brdf/", 0) == 0 && path.find('/', 5) != std::string::npos) return path.substr(path.find('/', 5) + 1);
    return "glsl/" + path;
}

struct Composer {
    const ExtraSources& extra;
    ComposedShader out;
    std::map<std::string, int> numbers;  // path -> its source-string number
    std::vector<std::string> open;       // files being included, outermost first

    const char* find(const std::string& path) const {
        for (const auto& [name, text] : extra)
            if (name == path) return text.c_str();
        return find_glsl_source(path);
    }

    int number_of(const std::string& path) {
        const auto [it, added] = numbers.emplace(path, int(out.files.size()));
        if (added) out.files.push_back(shown_name(path));
        return it->second;
    }

    void append(const std::string& path, const std::string& from) {
        if (std::find(open.begin(), open.end(), path) != open.end())
            throw std::runtime_error(from + ": \"" + path + "\" includes itself");
        const char* text = find(path);
        if (!text) throw std::runtime_error(from + ": unknown glsl file \"" + path + "\"");
        const std::string number = std::to_string(number_of(path));
        const std::string guard = "M3055_INCLUDED_" + number;
        open.push_back(path);
        // A .brdf block's lines are numbered from kBrdfLineBase x its number: Mesa
        // names some errors' source as 0, and the line alone then still says whose.
        const bool brdf = path.rfind("brdf/", 0) == 0;
        const int base = brdf ? kBrdfLineBase * std::stoi(number) : 0;
        if (brdf) out.user_files.push_back(out.files.back());
        out.text += "#ifndef " + guard + "\n#define " + guard + "\n#line " + std::to_string(base + 1) + " " + number + "\n";
        std::istringstream lines(text);
        std::string line;
        int line_number = 0;
        while (std::getline(lines, line)) {
            ++line_number;
            static const std::regex include(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
            std::smatch match;
            if (std::regex_match(line, match, include)) {
                append(match[1].str(), out.files[std::size_t(std::stoi(number))] + ":" + std::to_string(line_number));
                out.text += "#line " + std::to_string(base + line_number + 1) + " " + number + "\n";
            } else if (line.rfind("#version", 0) == 0) {
                out.text += "\n";  // the composed shader's #version comes first, once
            } else {
                out.text += line + "\n";
            }
        }
        out.text += "#endif\n";
        open.pop_back();
    }
};

}  // namespace

std::string glsl_header(GlslTarget target) {
    if (target == GlslTarget::desktop) return "#version 330 core\n";
    return "#version 300 es\n"
           "precision highp float;\n"
           "precision highp int;\n"
           "precision highp sampler2D;\n"
           "#define M3055_GLSL_ES 1\n";
}

ComposedShader compose_shader(const std::string& path, const std::vector<std::string>& defines, GlslTarget target) {
    return compose_shader(path, defines, generated_glsl(target == GlslTarget::es), target);
}

ComposedShader compose_shader(const std::string& path, const std::vector<std::string>& defines,
                              const ExtraSources& extra, GlslTarget target) {
    Composer composer{extra, {}, {}, {}};
    composer.out.text = glsl_header(target);
    for (const auto& define : defines) composer.out.text += "#define " + define + "\n";
    composer.append(path, "compose_shader");
    return composer.out;
}

namespace {

// A source position: the source-string number and its line, a .brdf block's
// (numbered from kBrdfLineBase x its number by compose_shader) as its own.
std::string position(const std::string& number, const std::string& line_text,
                     const std::vector<std::string>& files) {
    std::size_t file = std::stoul(number);
    std::string line = line_text;
    if (line.size() < 11 && std::stol(line) > kBrdfLineBase) {
        file = std::size_t(std::stol(line) / kBrdfLineBase);
        line = std::to_string(std::stol(line) % kBrdfLineBase);
    }
    return (file < files.size() ? files[file] : "source " + number) + ":" + line;
}

}  // namespace

std::string annotate_shader_log(const std::string& log, const std::vector<std::string>& files) {
    // Mesa writes "0:12(5): error: ...", other drivers "0(12) : error ...",
    // ANGLE (WebGL) "ERROR: 0:12: ..." (written here as "FILE:12: error: ...").
    static const std::regex prefix(
        R"((^|\n)(?:(\d+)(?::(\d+)\((\d+)\)|\((\d+)\))|(ERROR|WARNING): (\d+):(\d+):))");
    std::string result;
    auto begin = log.cbegin();
    std::smatch match;
    while (std::regex_search(begin, log.cend(), match, prefix)) {
        result.append(begin, match[0].first);
        result += match[1].str();
        if (match[6].matched) {
            result += position(match[7].str(), match[8].str(), files) + ": " +
                      (match[6].str() == "ERROR" ? "error:" : "warning:");
        } else {
            result += position(match[2].str(), match[3].matched ? match[3].str() : match[5].str(), files);
            if (match[4].matched) result += ":" + match[4].str();
        }
        begin = match[0].second;
    }
    result.append(begin, log.cend());
    // The .brdf code's names as its author wrote them (brdf_file/brdf_glsl.h renames them).
    static const std::regex renamed("m3055_b[0-9]+_n");
    return std::regex_replace(result, renamed, "");
}

}  // namespace m3055
