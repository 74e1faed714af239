// A class's submissions folder (docs/grading.md#submissions): one scene file
// per student (`alice.json`) or one folder per student (`alice/scene.json`,
// optional `alice/screenshot.png`). Names are sorted bytewise, so every node
// of a cluster computes the same order and the same shards.
#pragma once

#include <string>
#include <vector>

namespace m3055::grading {

struct Submission {
    std::string student;     // the file's stem or the folder's name
    std::string scene;       // path of the scene file
    std::string screenshot;  // path of screenshot.png, or "" when there is none
    std::string problem;     // why it cannot be graded ("alice/scene.json: missing"), or ""
};

// Every NAME.json and every folder (hidden entries, starting with '.', and
// other files skipped), sorted by student name; or, when `folder` is a .json
// file, that one submission (a student checking what they will submit). A name the outputs reserve
// (reference, grades, report, results) or that would clash with another's
// difference image (x-diff beside x) gets a `problem`. Throws
// std::runtime_error when the folder cannot be read.
std::vector<Submission> find_submissions(const std::string& folder);

// Shard K of N (1-based): the items whose index i in the sorted list has
// i % N == K - 1. Every item is in exactly one shard.
struct Shard {
    int k = 1, n = 1;
};
// Parses "K/N" (1 <= K <= N <= 100000); throws std::invalid_argument with one line.
Shard parse_shard(const std::string& text);
std::vector<Submission> take_shard(const std::vector<Submission>& all, Shard shard);

}  // namespace m3055::grading
