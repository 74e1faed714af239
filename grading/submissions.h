// A class's submissions folder (docs/grading.md#submissions): one scene file
// per student (`alice.json`) or one folder per student (`alice/scene.json`,
// optional `alice/screenshot.png`). Names are sorted bytewise, so every node
// of a cluster computes the same order and the same shards.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace m3055::grading {

struct Submission {
    std::string name;        // the file's stem or the folder's name: bytes, any but '/' and NUL
    std::string student;     // the name as every output shows it: shown_name(name)
    std::string file_stem;   // what the student's output files are named after: output_stem, unique in the class
    std::string scene;       // path of the scene file
    std::string folder;      // the submission's own folder (NAME/), where its .brdf files must be; "" for NAME.json
    std::string screenshot;  // path of screenshot.png, or "" when there is none
    std::string problem;     // why it cannot be graded ("alice/scene.json: missing"), or ""
    bool missing = false;    // on the roster, nothing submitted (problem "no submission")
    // Information for the teacher, no penalty: "not on the roster", "a
    // symbolic link to bob.json", "byte-identical to: bob, carol".
    std::vector<std::string> notes;
};

// An entry of the class folder that is not graded, and why ("hidden", "not a
// .json file or a folder").
struct Ignored {
    std::string name;  // shown_name of the entry's name
    std::string why;
};

struct ClassOptions {
    std::string roster;            // a file of names, one a line, or ""
    bool follow_symlinks = false;  // grade links that stay inside the folder (refused otherwise)
};

struct ClassFolder {
    std::vector<Submission> submissions;  // sorted bytewise by name
    std::vector<Ignored> ignored;         // sorted bytewise by name
    // Groups of students (shown names) whose scene files are byte-identical.
    std::vector<std::vector<std::string>> identical;
    // "COUNT:DIGEST" of every submission's name and its files' sizes and
    // digests, in order: the same on every node that reads the same class.
    std::string fingerprint;
};

// 32 hex digits of two FNV-1a passes (forward and backward) over `bytes`: a
// digest to tell accidents apart (another class, an edited file), not one
// that resists someone forging a collision.
std::string content_digest(std::string_view bytes);

// A file name (bytes) as text every output shows (CSV, JSON, HTML, the
// console): valid UTF-8, one line, and a different text for different bytes:
// invalid UTF-8 bytes as \xHH, controls as \n or \uXXXX, and \ and " escaped
// ("caf\xE9 latin1" for the Latin-1 bytes of "café latin1"). A plain name is
// shown as it is.
std::string shown_name(std::string_view name);

// A name for a student's output files, safe on any filesystem and in a link
// of the report: ASCII letters, digits, '-', '_', '.' and ' ' (neither first
// nor last) and printable non-ASCII UTF-8 are kept ("with space" stays "with
// space"); every other byte becomes '_' and the stem ends with "~" and 16 hex
// digits of a digest of the whole name, so different names give different
// stems; a longer one is cut to at most kMaxStemBytes, with the digest too.
inline constexpr std::size_t kMaxStemBytes = 200;
std::string output_stem(std::string_view name);

// Every NAME.json (the extension in any case: .JSON) and every folder NAME/,
// sorted by name bytewise; or, when `folder` is a .json file, that one
// submission (a student checking what they will submit). What else the folder
// holds is listed in `ignored`. A submission that is a symbolic link (or whose
// scene.json or screenshot.png is one) gets a `problem`, unless
// `follow_symlinks` and it resolves inside the folder (then a note). The same
// name as a file and as a folder (pat.json, pat/) or in two cases of the
// extension is one submission with a `problem`. With a roster, each name on it
// without a submission gets one (`missing`, "no submission") and a submission
// not on it a note. No name is refused for an output's sake: the students'
// files have folders of their own (grade_outputs.h: students/, diffs/). Stems
// that differ only by ASCII case (alice, Alice: one file on a case-insensitive
// disk) get "~" and a digest of the name appended. Throws std::runtime_error (one line) when the folder or the
// roster cannot be read, or the roster is malformed.
ClassFolder read_class(const std::string& folder, const ClassOptions& options = {});
// read_class(folder).submissions.
std::vector<Submission> find_submissions(const std::string& folder);

// Reads a roster: one name a line (a trailing \r dropped, blank lines
// skipped); a name with '/' or NUL, "." or "..", or given twice is an error
// naming the file and the line.
std::vector<std::string> read_roster(const std::string& path);

// Shard K of N (1-based): the items whose index i in the sorted list has
// i % N == K - 1. Every item is in exactly one shard.
struct Shard {
    int k = 1, n = 1;
};
// Parses "K/N" (1 <= K <= N <= 100000); throws std::invalid_argument with one line.
Shard parse_shard(const std::string& text);
std::vector<Submission> take_shard(const std::vector<Submission>& all, Shard shard);

}  // namespace m3055::grading
