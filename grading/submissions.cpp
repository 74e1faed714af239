#include "grading/submissions.h"

#include "io/message_text.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <stdexcept>

namespace m3055::grading {

namespace fs = std::filesystem;

namespace {

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

bool ends_with_json(const std::string& name) {
    if (name.size() <= 5) return false;
    std::string ext = name.substr(name.size() - 5);
    for (char& c : ext) c = (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
    return ext == ".json";
}

// Whether `path`, after every link, is inside `root` (itself excluded).
bool resolves_inside(const fs::path& path, const fs::path& root) {
    std::error_code error;
    const fs::path target = fs::canonical(path, error);
    if (error) return false;
    const fs::path base = fs::canonical(root, error);
    if (error) return false;
    auto r = base.begin(), t = target.begin();
    for (; r != base.end() && t != target.end(); ++r, ++t)
        if (*r != *t) return false;
    return r == base.end() && t != target.end();
}

// The path of `path` relative to the class folder `root`, shown, for a note.
std::string shown_inside(const fs::path& path, const fs::path& root) {
    std::error_code error;
    const fs::path relative = fs::canonical(path, error).lexically_relative(fs::canonical(root, error));
    return text::quote_name(relative.string());
}

// `path` (shown as `shown`) is a link: a problem, or with --follow-symlinks
// and a target inside the class folder, a note.
void check_link(Submission& s, const fs::path& path, const std::string& shown, const fs::path& root,
                const ClassOptions& options) {
    std::error_code error;
    if (!fs::is_symlink(path, error) || !s.problem.empty()) return;
    if (!options.follow_symlinks)
        s.problem = shown + ": a symbolic link: refused (m3055 grade --follow-symlinks grades links that stay inside "
                            "the submissions folder)";
    else if (!resolves_inside(path, root))
        s.problem = shown + ": a symbolic link out of the submissions folder: refused";
    else
        s.notes.push_back(shown + " is a symbolic link to " + shown_inside(path, root));
}

Submission from_entry(const fs::directory_entry& entry, const fs::path& root, const ClassOptions& options) {
    Submission s;
    const std::string name = entry.path().filename().string();
    std::error_code error;
    if (entry.is_directory(error)) {
        s.name = name;
        s.folder = entry.path().string();
        s.scene = (entry.path() / "scene.json").string();
        check_link(s, entry.path(), text::quote_name(name + "/"), root, options);
        std::error_code read_error;
        fs::directory_iterator probe(entry.path(), read_error);
        if (s.problem.empty() && read_error)
            s.problem = text::quote_name(name + "/") + ": cannot read the folder: " + read_error.message();
        const bool scene = fs::exists(fs::symlink_status(s.scene, error));
        if (s.problem.empty() && !scene) s.problem = text::quote_name(name + "/scene.json") + ": missing";
        check_link(s, s.scene, text::quote_name(name + "/scene.json"), root, options);
        const fs::path shot = entry.path() / "screenshot.png";
        if (fs::exists(fs::symlink_status(shot, error))) {
            s.screenshot = shot.string();
            check_link(s, shot, text::quote_name(name + "/screenshot.png"), root, options);
        }
    } else {
        s.name = name.substr(0, name.size() - 5);
        s.scene = entry.path().string();
        check_link(s, entry.path(), text::quote_name(name), root, options);
    }
    s.student = shown_name(s.name);
    s.file_stem = output_stem(s.name);
    return s;
}

// The folder's NAME.json files and NAME/ folders, or one scene file (a
// student checking the file they will submit); what else is there in `ignored`.
std::vector<Submission> list_entries(const std::string& folder, const ClassOptions& options,
                                     std::vector<Ignored>& ignored) {
    std::vector<Submission> all;
    std::error_code error;
    if (fs::is_regular_file(folder, error)) {
        if (!ends_with_json(fs::path(folder).filename().string()))
            throw std::runtime_error(text::quote_name(folder) + ": not a submissions folder nor a .json scene file");
        all.push_back(from_entry(fs::directory_entry(folder), fs::absolute(folder).parent_path(), options));
        return all;
    }
    fs::directory_iterator it(folder, error);
    if (error) throw std::runtime_error(text::quote_name(folder) + ": cannot read the submissions folder: " + error.message());
    for (const fs::directory_entry& entry : it) {
        const std::string name = entry.path().filename().string();
        if (name.empty()) continue;
        if (name[0] == '.') {
            ignored.push_back({name, "hidden (its name starts with \".\")"});
            continue;
        }
        std::error_code type_error;
        const bool folder_entry = entry.is_directory(type_error);
        if (folder_entry || ends_with_json(name)) {
            all.push_back(from_entry(entry, folder, options));
            continue;
        }
        std::string why = "not a .json file nor a folder";
        if (entry.is_symlink(type_error) && !entry.exists(type_error)) why = "a broken symbolic link";
        else if (name.find(".json") != std::string::npos || name.find(".JSON") != std::string::npos)
            why = "not a .json file nor a folder: the name does not end in .json";
        ignored.push_back({name, why});
    }
    return all;
}

// Byte-identical scene files, among those that can be graded: groups of two
// or more, each noted on its students.
// "SIZE:DIGEST" of a regular file of at most 16 MiB (a scene's limit), or ""
// when it is not one or cannot be read (never opened otherwise: a FIFO would block).
std::string file_digest(const std::string& path) {
    std::error_code error;
    if (!fs::is_regular_file(path, error)) return "";
    const std::uintmax_t size = fs::file_size(path, error);
    if (error || size > (std::uintmax_t(16) << 20)) return "";
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (!in.eof() && in.fail()) return "";
    return std::to_string(bytes.size()) + ":" + content_digest(bytes);
}

// Byte-identical scene files, among those that can be graded: groups of two
// or more, each noted on its students. Also the class's fingerprint: every
// submission's name, and its files' sizes and digests, in order.
std::vector<std::vector<std::string>> find_identical(std::vector<Submission>& all, std::string& fingerprint) {
    std::map<std::string, std::vector<std::size_t>> by_digest;  // "size:digest" -> indices
    std::string listing;
    for (std::size_t i = 0; i < all.size(); ++i) {
        const Submission& s = all[i];
        listing += s.name + '\0';
        if (!s.problem.empty()) {
            listing += "-\n";
            continue;
        }
        const std::string digest = file_digest(s.scene);
        listing += digest + (s.screenshot.empty() ? "" : " " + file_digest(s.screenshot)) + "\n";
        if (!digest.empty()) by_digest[digest].push_back(i);
    }
    fingerprint = std::to_string(all.size()) + ":" + content_digest(listing);
    std::vector<std::vector<std::string>> groups;
    for (const auto& [key, indices] : by_digest) {
        if (indices.size() < 2) continue;
        std::vector<std::string> names;
        for (std::size_t i : indices) names.push_back(all[i].student);
        for (std::size_t i : indices) {
            std::string others;
            for (std::size_t j : indices)
                if (j != i) others += (others.empty() ? "" : ", ") + all[j].student;
            all[i].notes.push_back("its scene file is byte-identical to that of " + others);
        }
        groups.push_back(std::move(names));
    }
    std::sort(groups.begin(), groups.end());
    return groups;
}

}  // namespace

std::string shown_name(std::string_view name) { return text::escape(name, true); }

std::string content_digest(std::string_view bytes) {
    return digest_hex(bytes) + digest_hex(std::string(bytes.rbegin(), bytes.rend()));
}

std::string output_stem(std::string_view name) {
    std::string out;
    bool replaced = false;
    for (std::size_t i = 0; i < name.size();) {
        const unsigned char c = static_cast<unsigned char>(name[i]);
        // A leading or trailing space or dot is lost or hidden on some disks.
        const bool edge = i == 0 || i + 1 == name.size();
        const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
                           c == '_' || ((c == '.' || c == ' ') && !edge);
        if (plain) {
            out += char(c);
            ++i;
            continue;
        }
        if (const std::size_t length = c >= 0x80 ? text::shown_multibyte_length(name, i) : 0) {
            out.append(name.substr(i, length));
            i += length;
            continue;
        }
        out += '_';
        replaced = true;
        ++i;
    }
    // A stem with a byte replaced ends with the whole name's digest, so
    // "a\nb" and "a_b" stay apart ('~' is never kept, so no plain name ends so).
    if (!replaced && out.size() <= kMaxStemBytes) return out;
    std::size_t cut = std::min(out.size(), kMaxStemBytes - 17);
    while (cut > 0 && cut < out.size() && (static_cast<unsigned char>(out[cut]) & 0xC0) == 0x80) --cut;  // not inside a character
    return with_digest(out.substr(0, cut), name);
}

std::vector<std::string> read_roster(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(text::quote_name(path) + ": --roster: cannot read the file");
    std::vector<std::string> names;
    std::set<std::string> seen;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos) continue;
        const std::string where = text::quote_name(path) + ":" + std::to_string(number) + ": ";
        if (line.find('/') != std::string::npos || line.find('\0') != std::string::npos || line == "." || line == "..")
            throw std::runtime_error(where + text::quote(line) + " is not a file name (a student's NAME.json or NAME/)");
        if (!seen.insert(line).second) throw std::runtime_error(where + text::quote(line) + " is on the roster twice");
        names.push_back(line);
    }
    if (in.bad()) throw std::runtime_error(text::quote_name(path) + ": --roster: cannot read the file");
    return names;
}

ClassFolder read_class(const std::string& folder, const ClassOptions& options) {
    ClassFolder out;
    std::vector<Submission> all = list_entries(folder, options, out.ignored);
    const std::vector<std::string> roster = options.roster.empty() ? std::vector<std::string>{} : read_roster(options.roster);
    // Bytewise, so every node of a cluster computes the same order.
    std::stable_sort(all.begin(), all.end(), [](const Submission& a, const Submission& b) { return a.name < b.name; });
    // One name twice (pat.json and pat/, or pat.json and pat.JSON): one row, with the reason.
    for (std::size_t i = 0; i + 1 < all.size();) {
        if (all[i].name != all[i + 1].name) {
            ++i;
            continue;
        }
        const bool folder_too = !all[i].folder.empty() || !all[i + 1].folder.empty();
        all[i].problem = text::quote_name(all[i].name) + ": submitted twice (" +
                         (folder_too ? "as a file and as a folder" : "as two .json files differing in the case of .json") +
                         "): one submission a student";
        all[i].folder.clear();
        all[i].notes.clear();
        all.erase(all.begin() + std::ptrdiff_t(i) + 1);
    }
    if (!options.roster.empty()) {
        const std::set<std::string> listed(roster.begin(), roster.end());
        std::set<std::string> submitted;
        for (Submission& s : all) {
            submitted.insert(s.name);
            if (!listed.count(s.name)) s.notes.push_back("not on the roster");
        }
        for (const std::string& name : roster) {
            if (submitted.count(name)) continue;
            Submission s;
            s.name = name;
            s.student = shown_name(name);
            s.file_stem = output_stem(name);
            s.missing = true;
            s.problem = "no submission";
            all.push_back(std::move(s));
        }
        std::stable_sort(all.begin(), all.end(), [](const Submission& a, const Submission& b) { return a.name < b.name; });
    }
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
    out.identical = find_identical(all, out.fingerprint);
    std::sort(out.ignored.begin(), out.ignored.end(), [](const Ignored& a, const Ignored& b) { return a.name < b.name; });
    for (Ignored& entry : out.ignored) entry.name = shown_name(entry.name);
    out.submissions = std::move(all);
    return out;
}

std::vector<Submission> find_submissions(const std::string& folder) { return read_class(folder).submissions; }

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
