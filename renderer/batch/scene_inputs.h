// `m3055 batch --out DIR SCENES...`: scene files named on the command line as
// files, folders (their *.json, not recursive) or glob patterns (quoted, so the
// program expands them: a class of 10 000 files does not meet the shell's
// argument limit). The list is sorted and without repeats, so `--shard K/N`
// splits it the same way on every node.
#pragma once

#include <string>
#include <vector>

namespace m3055 {

// Throws std::runtime_error with one line for a folder that cannot be read or
// a pattern or name that matches nothing.
std::vector<std::string> expand_scene_inputs(const std::vector<std::string>& inputs);

// "DIR/NAME.png" for "some/where/NAME.json" (`extension` with its dot).
std::string output_for(const std::string& scene, const std::string& out_dir, const std::string& extension);

}  // namespace m3055
