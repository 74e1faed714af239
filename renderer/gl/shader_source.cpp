#include "gl/shader_source.h"

#include "gl/glsl_sources.h"

#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

namespace m3055 {

const char* find_glsl_source(const std::string& path) {
    for (const auto& source : glsl_sources())
        if (path == source.path) return source.text;
    return nullptr;
}

namespace {

struct Composer {
    ComposedShader out;
    std::set<std::string> included;

    void append(const std::string& path, const std::string& from) {
        if (!included.insert(path).second) return;
        const char* text = find_glsl_source(path);
        if (!text) throw std::runtime_error(from + ": unknown glsl file \"" + path + "\"");
        const int number = int(out.files.size());
        out.files.push_back(path);
        std::istringstream lines(text);
        std::string line;
        int line_number = 0;
        out.text += "#line 1 " + std::to_string(number) + "\n";
        while (std::getline(lines, line)) {
            ++line_number;
            static const std::regex include(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
            std::smatch match;
            if (std::regex_match(line, match, include)) {
                append(match[1].str(), "glsl/" + path + ":" + std::to_string(line_number));
                out.text += "#line " + std::to_string(line_number + 1) + " " + std::to_string(number) + "\n";
            } else if (line.rfind("#version", 0) == 0) {
                out.text += "\n";  // the composed shader's #version comes first, once
            } else {
                out.text += line + "\n";
            }
        }
    }
};

}  // namespace

ComposedShader compose_shader(const std::string& path, const std::vector<std::string>& defines) {
    Composer composer;
    composer.out.text = "#version 330 core\n";
    for (const auto& define : defines) composer.out.text += "#define " + define + "\n";
    composer.append(path, "compose_shader");
    return composer.out;
}

std::string annotate_shader_log(const std::string& log, const std::vector<std::string>& files) {
    // Mesa writes "0:12(5): error: ...", other drivers "0(12) : error ...".
    static const std::regex prefix(R"((^|\n)(\d+)(?::(\d+)\((\d+)\)|\((\d+)\)))");
    std::string result;
    auto begin = log.cbegin();
    std::smatch match;
    while (std::regex_search(begin, log.cend(), match, prefix)) {
        result.append(begin, match[0].first);
        const std::size_t file = std::stoul(match[2].str());
        const std::string line = match[3].matched ? match[3].str() : match[5].str();
        result += match[1].str();
        result += file < files.size() ? "glsl/" + files[file] : "source " + match[2].str();
        result += ":" + line;
        if (match[4].matched) result += ":" + match[4].str();
        begin = match[0].second;
    }
    result.append(begin, log.cend());
    return result;
}

}  // namespace m3055
