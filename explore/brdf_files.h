// The explorer's .brdf files (issue 13): File > Open BRDF and a drop apply a
// file to the selected object, and the files in use are watched (their mtime
// and size polled twice a second: one stat each) and re-read when saved,
// keeping the current parameter values. A parse or GLSL error leaves the
// materials as they were (the last good version keeps rendering) and is kept
// in state.brdf_error, in the file's own line numbers, until the file is
// fixed. No ImGui and no GL here: the GLSL check is state.brdf_compile_check.
#pragma once

#include "explore/state.h"

#include <string>
#include <vector>

namespace m3055::explore {

inline constexpr double kBrdfPollSeconds = 0.5;

// A path naming a .brdf file (by its extension, any case).
bool is_brdf_path(const std::string& path);

// Applies `path` to the selected object, with the file's defaults (one undo
// step "open NAME"). On a parse or GLSL error: state.brdf_error and
// state.load_error are set, nothing else changes, false.
bool open_brdf(ExplorerState& state, const std::string& path);

// The .brdf files the scene's materials and the compare's B use, each once.
std::vector<std::string> brdf_files_in_use(const ExplorerState& state);

// At most every kBrdfPollSeconds (`now` in seconds): each file in use whose
// mtime or size changed is noted in state.brdf_reload_pending (a frame shows
// "reloading FILE..."); the next call re-reads and checks them, and on success
// every material using one is reloaded (reload_brdf_material: values kept) and
// the status says "reloaded FILE". Returns true when there is something new to show.
bool poll_brdf_files(ExplorerState& state, double now);

}  // namespace m3055::explore
