#include "grading/folder_compare.h"

#include "grading/image_input.h"
#include "grading/submissions.h"
#include "io/message_text.h"

#include <filesystem>
#include <set>
#include <stdexcept>

namespace m3055::grading {

namespace fs = std::filesystem;

namespace {

// The names of the PNG files of `folder`, bytewise sorted.
std::set<std::string> png_names(const std::string& folder, const char* which) {
    std::error_code error;
    fs::directory_iterator it(folder, error);
    if (error)
        throw std::runtime_error(text::quote_name(folder) + ": " + which + ": cannot read the folder: " + error.message());
    std::set<std::string> names;
    for (const fs::directory_entry& entry : it) {
        const std::string name = entry.path().filename().string();
        std::error_code type_error;
        if (input_kind(name) == InputKind::png && entry.is_regular_file(type_error)) names.insert(name);
    }
    return names;
}

}  // namespace

std::size_t FolderComparison::count(Verdict verdict) const {
    std::size_t n = 0;
    for (const PngPair& pair : pairs) n += pair.comparison && pair.comparison->verdict == verdict ? 1 : 0;
    return n;
}

std::size_t FolderComparison::problems() const {
    std::size_t n = 0;
    for (const PngPair& pair : pairs) n += pair.comparison ? 0 : 1;
    return n;
}

FolderComparison compare_folders(const std::string& a, const std::string& b, int bits, const Thresholds& thresholds) {
    const std::set<std::string> in_a = png_names(a, "A"), in_b = png_names(b, "B");
    FolderComparison out;
    for (const std::string& name : in_a) {
        if (!in_b.count(name)) {
            out.only_a.push_back(shown_name(name));
            continue;
        }
        PngPair pair;
        pair.name = shown_name(name);
        try {
            const LevelImage image_a = read_level_image((fs::path(a) / name).string(), bits);
            const LevelImage image_b = read_level_image((fs::path(b) / name).string(), bits);
            pair.comparison = compare_levels(image_a, image_b, thresholds);
        } catch (const std::exception& e) {
            pair.problem = text::one_line(e.what());
        }
        out.pairs.push_back(std::move(pair));
    }
    for (const std::string& name : in_b)
        if (!in_a.count(name)) out.only_b.push_back(shown_name(name));
    return out;
}

}  // namespace m3055::grading
