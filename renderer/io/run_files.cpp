#include "io/run_files.h"

#include "io/input_file.h"
#include "io/message_text.h"

#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <unordered_map>

namespace m3055::io {
namespace {

// Where a path is, as far as it can be told without writing anything.
struct Resolved {
    std::vector<std::string> keys;  // identities: any key shared by two files makes them one file
    std::string problem;            // an output that cannot be written (""; inputs: always "")
};

std::string folder_of(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string name_of(const std::string& path) {
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// realpath(), or "" with the reason in `error`.
std::string real_path(const std::string& path, int& error) {
    char buffer[PATH_MAX];
    if (::realpath(path.c_str(), buffer)) return buffer;
    error = errno;
    return "";
}

std::string inode_key(const struct stat& info) {
    return "inode " + std::to_string(info.st_dev) + ":" + std::to_string(info.st_ino);
}

// Keys: "entry <real folder>/<name>" (the directory entry a write replaces),
// and for an existing file its inode; for an input also the entry its
// symlinks lead to. A folder that cannot be resolved leaves the path as
// written: reading or writing it fails later with its own message.
Resolved resolve(const std::string& path, bool output) {
    Resolved resolved;
    const std::string name = name_of(path);
    if (output && (name.empty() || name == "." || name == ".."))
        return {{}, "cannot write: not a file name (it names a folder)"};
    int error = 0;
    const std::string folder = real_path(folder_of(path), error);
    if (folder.empty()) {
        if (output) return {{}, std::string("cannot write into its folder: ") + std::strerror(error)};
        return {{"path " + path}, ""};
    }
    struct stat info {};
    if (output && (::stat(folder.c_str(), &info) != 0 || !S_ISDIR(info.st_mode)))
        return {{}, "cannot write into its folder: " + std::string(std::strerror(ENOTDIR))};
    const std::string entry = (folder == "/" ? "" : folder) + "/" + name;
    resolved.keys.push_back("entry " + entry);
    if (output) {
        const long name_max = ::pathconf(folder.c_str(), _PC_NAME_MAX);
        if (name_max > 0 && name.size() > std::size_t(name_max)) return {{}, std::string("cannot write: ") + std::strerror(ENAMETOOLONG)};
    }
    if (::lstat(entry.c_str(), &info) == 0) {
        if (output && !S_ISREG(info.st_mode))
            return {{}, std::string("cannot write: it is ") + describe_file_type(info.st_mode) +
                            ", not a regular file (outputs go only to regular files or new names)"};
        resolved.keys.push_back(inode_key(info));
        if (!output && S_ISLNK(info.st_mode)) {
            const std::string target = real_path(entry, error);
            if (!target.empty()) resolved.keys.push_back("entry " + target);
            if (::stat(entry.c_str(), &info) == 0) resolved.keys.push_back(inode_key(info));
        }
    } else if (errno != ENOENT && output) {
        return {{}, std::string("cannot write: ") + std::strerror(errno)};
    }
    return resolved;
}

}  // namespace

void RunFiles::add_input(Owner owner, const std::string& label, const std::string& path) {
    files_.push_back({owner, label, path, false});
}

void RunFiles::add_output(Owner owner, const std::string& label, const std::string& path) {
    files_.push_back({owner, label, path, true});
}

std::map<RunFiles::Owner, std::string> RunFiles::check(const std::string& prefix) const {
    std::map<Owner, std::string> problems;
    const auto report = [&](Owner owner, const std::string& message) { problems.emplace(owner, prefix + message); };
    const auto named = [](const File& file) { return file.label + " " + text::quote_name(file.path); };
    std::unordered_map<std::string, std::size_t> first_with_key;  // key -> index into files_
    for (std::size_t i = 0; i < files_.size(); ++i) {
        const File& file = files_[i];
        const Resolved resolved = resolve(file.path, file.output);
        if (!resolved.problem.empty()) report(file.owner, named(file) + ": " + resolved.problem);
        for (const std::string& key : resolved.keys) {
            const auto [it, inserted] = first_with_key.emplace(key, i);
            if (inserted) continue;
            const File& other = files_[it->second];
            if (!file.output && !other.output) continue;  // two entries may read one scene
            if (file.output && other.output) {
                report(file.owner, named(file) + ": is the same file as " + named(other));
                report(other.owner, named(other) + ": is the same file as " + named(file));
            } else {
                const File& writer = file.output ? file : other;
                const File& reader = file.output ? other : file;
                report(writer.owner, named(writer) + ": would overwrite " + named(reader));
                report(reader.owner, named(reader) + ": would be overwritten by " + named(writer));
            }
            break;  // one message per pair is enough
        }
    }
    return problems;
}

}  // namespace m3055::io
