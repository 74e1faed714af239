#include "batch/scene_inputs.h"

#include "io/message_text.h"

#include <glob.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

namespace m3055 {

namespace fs = std::filesystem;

namespace {

bool is_pattern(const std::string& text) { return text.find_first_of("*?[") != std::string::npos; }

void add_folder(const std::string& folder, std::vector<std::string>& out) {
    std::error_code error;
    fs::directory_iterator it(folder, error);
    if (error) throw std::runtime_error(text::quote_name(folder) + ": cannot read the folder: " + error.message());
    for (const fs::directory_entry& entry : it) {
        const std::string name = entry.path().filename().string();
        if (!name.empty() && name[0] != '.' && entry.path().extension() == ".json") out.push_back(entry.path().string());
    }
}

void add_pattern(const std::string& pattern, std::vector<std::string>& out) {
    glob_t found{};
    const int status = ::glob(pattern.c_str(), 0, nullptr, &found);
    if (status != 0) {
        globfree(&found);
        throw std::runtime_error(text::quote_name(pattern) + ": matches no file");
    }
    for (std::size_t i = 0; i < found.gl_pathc; ++i) out.push_back(found.gl_pathv[i]);
    globfree(&found);
}

}  // namespace

std::vector<std::string> expand_scene_inputs(const std::vector<std::string>& inputs) {
    std::vector<std::string> out;
    for (const std::string& input : inputs) {
        std::error_code error;
        if (fs::is_directory(input, error))
            add_folder(input, out);
        else if (!fs::exists(input, error) && is_pattern(input))
            add_pattern(input, out);
        else
            out.push_back(input);  // a missing file is reported as that scene's failure
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::string output_for(const std::string& scene, const std::string& out_dir, const std::string& extension) {
    return (fs::path(out_dir) / fs::path(scene).stem()).string() + extension;
}

}  // namespace m3055
