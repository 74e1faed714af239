// `m3055 compare A_DIR B_DIR` (docs/grading.md): the PNGs of two folders
// compared by name, each pair level by level as `compare A B` compares two
// images (the same thresholds), and the names found in one folder only: the
// renders of a class, of a batch or of two builds, side by side.
#pragma once

#include "grading/level_compare.h"

#include <optional>
#include <string>
#include <vector>

namespace m3055::grading {

// A name found in both folders.
struct PngPair {
    std::string name;                      // the file's name, as every output shows it (submissions.h: shown_name)
    std::optional<Comparison> comparison;  // when both images could be read and compared
    std::string problem;                   // otherwise why not, one line ("sizes differ: A is ..., B is ...")
};

struct FolderComparison {
    std::vector<PngPair> pairs;       // bytewise order of the names
    std::vector<std::string> only_a;  // shown names of PNGs in A alone, in order
    std::vector<std::string> only_b;
    std::size_t count(Verdict verdict) const;
    std::size_t problems() const;  // pairs that could not be compared
};

// Every regular file of `a` and of `b` (not their subfolders) whose name ends
// in .png (any case), read at `bits` a channel. Throws (one line) when a
// folder cannot be read; an image that cannot be is its pair's problem.
FolderComparison compare_folders(const std::string& a, const std::string& b, int bits, const Thresholds& thresholds);

}  // namespace m3055::grading
