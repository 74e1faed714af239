// Mesa's on-disk shader cache on a disk that is full.
// Mesa maps its cache index file into memory; when the filesystem cannot
// allocate the pages, the first write through that mapping is a SIGBUS, which
// ends the process without a word. Checked before the first GL context is
// made, so that a run goes on without the cache instead.
#pragma once

#include <cstdint>
#include <string>

namespace m3055 {

// Free space below which the cache is not used (Mesa's index alone is 1.3 MB
// and it grows the cache up to 1 GB; this leaves a margin for other writers).
inline constexpr std::uint64_t kMinShaderCacheFreeBytes = std::uint64_t(64) << 20;

// The folder Mesa would use, as Mesa finds it: $MESA_SHADER_CACHE_DIR,
// $XDG_CACHE_HOME or ~/.cache, each + "/mesa_shader_cache"; "" when
// MESA_SHADER_CACHE_DISABLE (or the older MESA_GLSL_CACHE_DISABLE) is set true.
std::string mesa_shader_cache_folder();

// Where Mesa keeps this process's shader cache, set before the first context
// is made: `folder`/mesa_shader_cache (MESA_SHADER_CACHE_DIR, which wins over
// XDG_CACHE_HOME and ~/.cache). `grade` and `batch` keep it in their output
// folder: a student's .brdf is code, and its compiled shaders are not written
// to the teacher's home.
void keep_shader_cache_in(const std::string& folder);
// No on-disk shader cache for this process (before the first context).
void switch_shader_cache_off();

// When the cache folder (or the nearest folder above it that exists, where
// Mesa would create it) is not writable, not a folder, or has less than
// kMinShaderCacheFreeBytes or no inode free, sets MESA_SHADER_CACHE_DISABLE
// for this process and returns a one-line note saying so; otherwise "".
std::string disable_shader_cache_if_unusable();

}  // namespace m3055
