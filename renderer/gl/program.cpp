#include "gl/program.h"

#include "gl/shader_source.h"
#include "io/message_text.h"
#include "models/model_table.h"

#include <regex>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace m3055 {

std::string error_text(const std::exception& error) {
    if (dynamic_cast<const ShaderError*>(&error)) return std::string("m3055: ") + error.what();
    return text::one_line(std::string("m3055: ") + error.what());
}

bool ProgramKey::operator<(const ProgramKey& other) const {
    return std::tie(vertex, fragment, defines, table_revision) <
           std::tie(other.vertex, other.fragment, other.defines, other.table_revision);
}

static unsigned compile(const GlApi& gl, GLenum stage, const std::string& path,
                        const std::vector<std::string>& defines) {
    const ComposedShader source = compose_shader(path, defines);
    const unsigned shader = gl.CreateShader(stage);
    const char* text = source.text.c_str();
    gl.ShaderSource(shader, 1, &text, nullptr);
    gl.CompileShader(shader);
    GLint ok = 0;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(length > 0 ? length : 1), '\0');
        gl.GetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
        gl.DeleteShader(shader);
        while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
        const std::string annotated = annotate_shader_log(log, source.files);
        // An error in a .brdf file's code is the file's own: its first error, one line.
        std::istringstream lines(annotated);
        for (std::string line; std::getline(lines, line);)
            for (const std::string& file : source.user_files)
                if (line.rfind(file + ":", 0) == 0 && line.find("error") != std::string::npos) {
                    // FILE:LINE:COL: the column counts the renamed (longer) names, so it goes.
                    static const std::regex column("^(:[0-9]+):[0-9]+:");
                    throw ShaderError(file + std::regex_replace(line.substr(file.size()), column, "$1:"));
                }
        throw ShaderError("cannot compile glsl/" + path + ":\n" + annotated);
    }
    return shader;
}

unsigned build_program(const GlApi& gl, const ProgramKey& key) {
    const unsigned vertex = compile(gl, GL_VERTEX_SHADER, key.vertex, key.defines);
    unsigned fragment = 0;
    try {
        fragment = compile(gl, GL_FRAGMENT_SHADER, key.fragment, key.defines);
    } catch (...) {
        gl.DeleteShader(vertex);
        throw;
    }
    const unsigned program = gl.CreateProgram();
    gl.AttachShader(program, vertex);
    gl.AttachShader(program, fragment);
    gl.LinkProgram(program);
    gl.DeleteShader(vertex);
    gl.DeleteShader(fragment);
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(length > 0 ? length : 1), '\0');
        gl.GetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
        gl.DeleteProgram(program);
        throw ShaderError("cannot link glsl/" + key.vertex + " + glsl/" + key.fragment + ": " + log);
    }
    return program;
}

bool ProgramCache::contains(ProgramKey key) const {
    key.table_revision = model_table().revision();
    return programs_.count(key) > 0;
}

unsigned ProgramCache::get(ProgramKey key) {
    key.table_revision = model_table().revision();
    auto found = programs_.find(key);
    if (found != programs_.end()) return found->second.id();
    return programs_.emplace(key, GlProgram(gl_, build_program(gl_, key))).first->second.id();
}

}  // namespace m3055
