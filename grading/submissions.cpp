#include "grading/submissions.h"

#include "io/message_text.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <stdexcept>

namespace m3055::grading {

namespace fs = std::filesystem;

namespace {

bool is_reserved(const std::string& name) {
    return name == "reference" || name == "grades" || name == "report" || name == "results";
}

Submission from_entry(const fs::directory_entry& entry) {
    Submission s;
    const std::string name = entry.path().filename().string();
    std::error_code error;
    if (entry.is_directory(error)) {
        s.student = name;
        s.scene = (entry.path() / "scene.json").string();
        if (!fs::exists(s.scene, error)) s.problem = text::quote_name(name + "/scene.json") + ": missing";
        const fs::path shot = entry.path() / "screenshot.png";
        if (fs::exists(shot, error)) s.screenshot = shot.string();
    } else {
        s.student = entry.path().stem().string();
        s.scene = entry.path().string();
    }
    return s;
}

// The folder's NAME.json files and NAME/ folders, or one scene file (a
// student checking the file they will submit).
std::vector<Submission> list_entries(const std::string& folder) {
    std::vector<Submission> all;
    std::error_code error;
    if (fs::is_regular_file(folder, error)) {
        if (fs::path(folder).extension() != ".json")
            throw std::runtime_error(text::quote_name(folder) + ": not a submissions folder nor a .json scene file");
        all.push_back(from_entry(fs::directory_entry(folder)));
        return all;
    }
    fs::directory_iterator it(folder, error);
    if (error) throw std::runtime_error(text::quote_name(folder) + ": cannot read the submissions folder: " + error.message());
    for (const fs::directory_entry& entry : it) {
        const std::string name = entry.path().filename().string();
        if (name.empty() || name[0] == '.') continue;
        std::error_code type_error;
        const bool folder_entry = entry.is_directory(type_error);
        const bool json = entry.path().extension() == ".json";
        if (folder_entry || json) all.push_back(from_entry(entry));
    }
    return all;
}

}  // namespace

std::vector<Submission> find_submissions(const std::string& folder) {
    std::vector<Submission> all = list_entries(folder);
    std::sort(all.begin(), all.end(), [](const Submission& a, const Submission& b) { return a.student < b.student; });
    std::set<std::string> names;
    for (const Submission& s : all) names.insert(s.student);
    for (std::size_t i = 0; i < all.size(); ++i) {
        Submission& s = all[i];
        if (!s.problem.empty()) continue;
        const std::string shown = text::quote_name(s.student);
        if (i > 0 && all[i - 1].student == s.student)
            s.problem = shown + ": submitted twice (as a file and as a folder)";
        else if (i + 1 < all.size() && all[i + 1].student == s.student)
            s.problem = shown + ": submitted twice (as a file and as a folder)";
        else if (is_reserved(s.student))
            s.problem = shown + ": the name is reserved for an output of grade; rename the submission";
        else if (s.student.size() > 5 && s.student.compare(s.student.size() - 5, 5, "-diff") == 0 &&
                 names.count(s.student.substr(0, s.student.size() - 5)))
            s.problem = shown + ": its image would overwrite the difference image of " +
                        text::quote_name(s.student.substr(0, s.student.size() - 5)) + "; rename the submission";
    }
    return all;
}

Shard parse_shard(const std::string& text) {
    const std::size_t slash = text.find('/');
    const auto bad = [&]() {
        throw std::invalid_argument("--shard " + text::quote_name(text) + ": expected K/N with 1 <= K <= N, e.g. 2/4");
    };
    if (slash == std::string::npos || slash == 0 || slash + 1 >= text.size()) bad();
    Shard shard;
    try {
        std::size_t used = 0;
        shard.k = std::stoi(text.substr(0, slash), &used);
        if (used != slash) bad();
        shard.n = std::stoi(text.substr(slash + 1), &used);
        if (used != text.size() - slash - 1) bad();
    } catch (const std::logic_error&) {
        bad();
    }
    if (shard.k < 1 || shard.n < 1 || shard.k > shard.n || shard.n > 100000) bad();
    return shard;
}

std::vector<Submission> take_shard(const std::vector<Submission>& all, Shard shard) {
    std::vector<Submission> out;
    for (std::size_t i = 0; i < all.size(); ++i)
        if (int(i % std::size_t(shard.n)) == shard.k - 1) out.push_back(all[i]);
    return out;
}

}  // namespace m3055::grading
