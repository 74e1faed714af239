// A file opened at one path and named in messages by another: a file of a
// folder other than the working one, named relative to that folder, so that
// `m3055 grade` says "alice/scene.json" however the class folder was typed,
// without changing the process's working folder.
#pragma once

#include <filesystem>
#include <string>

namespace m3055::io {

struct InputPath {
    std::string path;   // what is opened
    std::string shown;  // what messages name

    // `name` as the user or a file wrote it; opened inside `folder` when it is
    // relative and `folder` is not "" (the working folder).
    static InputPath in_folder(const std::string& folder, const std::string& name) {
        if (folder.empty() || name.empty() || std::filesystem::path(name).is_absolute()) return {name, name};
        return {(std::filesystem::path(folder) / name).string(), name};
    }
    // A path opened and named as it is.
    static InputPath as_given(const std::string& path) { return {path, path}; }
};

}  // namespace m3055::io
