#include "grading/submissions.h"

#include "io/message_text.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

namespace m3055::grading {

namespace fs = std::filesystem;

namespace {

// Length of the well-formed UTF-8 sequence at s[i] of 2 to 4 bytes whose
// code point is printable (U+00A0 and up, none of the controls
// text::escape shows as \uXXXX); 0 otherwise.
std::size_t printable_utf8(std::string_view s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
    const unsigned char c = byte(0);
    std::size_t length = 0;
    char32_t cp = 0, min = 0;
    if ((c & 0xE0) == 0xC0) length = 2, cp = c & 0x1F, min = 0x80;
    else if ((c & 0xF0) == 0xE0) length = 3, cp = c & 0x0F, min = 0x800;
    else if ((c & 0xF8) == 0xF0) length = 4, cp = c & 0x07, min = 0x10000;
    else return 0;
    if (i + length > s.size()) return 0;
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(k) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (byte(k) & 0x3F);
    }
    if (cp < min || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF) return 0;
    if (cp < 0xA0 || cp == 0x2028 || cp == 0x2029 || cp == 0x200E || cp == 0x200F || (cp >= 0x202A && cp <= 0x202E) ||
        (cp >= 0x2066 && cp <= 0x2069) || cp == 0xFEFF)
        return 0;
    return length;
}

std::string digest_hex(std::string_view bytes) {
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(h));
    return out;
}

std::string with_digest(const std::string& stem, std::string_view name) {
    return stem + "~" + digest_hex(name);
}

bool is_reserved(const std::string& name) {
    return name == "reference" || name == "grades" || name == "report" || name == "results";
}

Submission from_entry(const fs::directory_entry& entry) {
    Submission s;
    const std::string name = entry.path().filename().string();
    std::error_code error;
    if (entry.is_directory(error)) {
        s.name = name;
        s.folder = entry.path().string();
        s.scene = (entry.path() / "scene.json").string();
        if (!fs::exists(s.scene, error)) s.problem = text::quote_name(name + "/scene.json") + ": missing";
        const fs::path shot = entry.path() / "screenshot.png";
        if (fs::exists(shot, error)) s.screenshot = shot.string();
    } else {
        s.name = entry.path().stem().string();
        s.scene = entry.path().string();
    }
    s.student = shown_name(s.name);
    s.file_stem = output_stem(s.name);
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

std::string shown_name(std::string_view name) { return text::escape(name, true); }

std::string output_stem(std::string_view name) {
    std::string out;
    for (std::size_t i = 0; i < name.size();) {
        const unsigned char c = static_cast<unsigned char>(name[i]);
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
                           c == '_' || (c == '.' && i > 0);
        if (plain) {
            out += char(c);
            ++i;
            continue;
        }
        if (const std::size_t length = c >= 0x80 ? printable_utf8(name, i) : 0) {
            out.append(name.substr(i, length));
            i += length;
            continue;
        }
        char escaped[4];
        std::snprintf(escaped, sizeof escaped, "%%%02X", unsigned(c));
        out += escaped;
        ++i;
    }
    if (out.size() <= kMaxStemBytes) return out;
    // Cut on a character boundary (not inside a %HH nor a UTF-8 sequence).
    std::size_t cut = kMaxStemBytes - 17;
    while (cut > 0 && (static_cast<unsigned char>(out[cut]) & 0xC0) == 0x80) --cut;
    if (cut >= 1 && out[cut - 1] == '%') cut -= 1;
    else if (cut >= 2 && out[cut - 2] == '%') cut -= 2;
    return with_digest(out.substr(0, cut), name);
}

std::vector<Submission> find_submissions(const std::string& folder) {
    std::vector<Submission> all = list_entries(folder);
    // Bytewise, so every node of a cluster computes the same order.
    std::stable_sort(all.begin(), all.end(), [](const Submission& a, const Submission& b) { return a.name < b.name; });
    // Stems one case-insensitive disk would hold as one file get the name's digest.
    std::map<std::string, int> folded;
    const auto fold = [](std::string stem) {
        for (char& c : stem) c = (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
        return stem;
    };
    for (const Submission& s : all) ++folded[fold(s.file_stem)];
    for (Submission& s : all)
        if (folded[fold(s.file_stem)] > 1 && s.file_stem.find('~') == std::string::npos)
            s.file_stem = with_digest(s.file_stem, s.name);
    std::map<std::string, std::string> stems;  // folded stem -> its name
    for (const Submission& s : all) stems[fold(s.file_stem)] = s.name;
    for (std::size_t i = 0; i < all.size(); ++i) {
        Submission& s = all[i];
        if (!s.problem.empty()) continue;
        const std::string shown = text::quote_name(s.name);
        if (i > 0 && all[i - 1].name == s.name)
            s.problem = shown + ": submitted twice (as a file and as a folder)";
        else if (i + 1 < all.size() && all[i + 1].name == s.name)
            s.problem = shown + ": submitted twice (as a file and as a folder)";
        else if (is_reserved(fold(s.file_stem)))
            s.problem = shown + ": the name is reserved for an output of grade; rename the submission";
        else if (const std::string stem = fold(s.file_stem);
                 stem.size() > 5 && stem.compare(stem.size() - 5, 5, "-diff") == 0 &&
                 stems.count(stem.substr(0, stem.size() - 5)))
            s.problem = shown + ": its image would overwrite the difference image of " +
                        text::quote_name(stems[stem.substr(0, stem.size() - 5)]) + "; rename the submission";
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
