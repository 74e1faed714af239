// The files one run reads and writes, checked together before anything is
// written: no output may be an input or another output of the run,
// however it is named (relative or absolute, through a symlinked folder, a
// hard link, a second name on a case-insensitive disk), and an output goes
// only to a regular file or a new name.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace m3055::io {

class RunFiles {
public:
    // Who names a file: an entry of a manifest, or the one command line (0).
    using Owner = std::size_t;
    // `label` names the file's role in messages: "--out", "[3].scene".
    void add_input(Owner owner, const std::string& label, const std::string& path);
    void add_output(Owner owner, const std::string& label, const std::string& path);

    // The first problem of each owner that has one, as a one-line message
    // (`prefix` first, e.g. "m.json: "):
    //   "[3].out a.png: would overwrite [5].scene a.png" (and for [5]:
    //   "[5].scene a.png: would be overwritten by [3].out a.png"),
    //   "[1].out ../o/a.png: is the same file as [0].out a.png",
    //   "--out /dev/null: cannot write: it is a character device, not a regular file ...",
    //   "[2].out missing/a.png: cannot write into its folder: No such file or directory".
    // Both owners of a clash get a message, so neither writes anything.
    std::map<Owner, std::string> check(const std::string& prefix = "") const;

private:
    struct File {
        Owner owner;
        std::string label, path;
        bool output;
    };
    std::vector<File> files_;
};

}  // namespace m3055::io
