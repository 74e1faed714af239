// The explorer's .brdf files: File > Open BRDF and a drop apply a
// file to the selected object, and the files in use are watched (their mtime
// and size polled twice a second: one stat each) and re-read when saved,
// keeping the current parameter values. A parse or GLSL error leaves the
// materials as they were (the last good version keeps rendering) and is kept
// in messages.brdf_error, in the file's own line numbers, until the file is
// fixed. No ImGui and no GL here: the GLSL check is the platform's brdf_compile_check.
#pragma once

#include "explore/explorer.h"

#include <string>
#include <vector>

namespace m3055::explore {

inline constexpr double kBrdfPollSeconds = 0.5;

// A path naming a .brdf file (by its extension, any case).
bool is_brdf_path(const std::string& path);

// Applies `path` to the selected object, with the file's defaults (one undo
// step "open NAME"). On a parse or GLSL error: messages.brdf_error and
// load_error are set, nothing else changes, false.
bool open_brdf(Explorer& explorer, const std::string& path);

// The .brdf files the scene's materials and the compare's B use, each once.
std::vector<std::string> brdf_files_in_use(const Explorer& explorer);
// The same, kept until the document's revision changes (what the frame loop asks every frame).
const std::vector<std::string>& watched_brdf_files(Explorer& explorer);

// At most every kBrdfPollSeconds (`now` in seconds): each file in use whose
// mtime or size changed is noted in brdf_watch.reload_pending (frames show
// "reloading FILE..." and keep drawing the last version). Returns true when
// one was found.
bool poll_brdf_files(Explorer& explorer, double now);
// Re-reads and checks the files noted (the frame loop calls it when it has
// been idle a while, as it compiles a waiting specialization: the check and
// the new programs take seconds on llvmpipe, and no frame waits for them); on
// success every material using one is reloaded (reload_brdf_material: values
// kept; one undo step) and the status says "reloaded FILE"; on an error the
// last version that compiled stays. Returns whether there were any.
bool reload_changed_brdf_files(Explorer& explorer);

}  // namespace m3055::explore
