// The context of a command that draws headless (a Capture's): made after the
// process has guarded itself against Mesa's shader cache on a full disk.
#pragma once

#include "gl/context.h"

#include <memory>

namespace m3055 {

// The folder of an output folder (`grade --out`, `batch --out`) that holds
// Mesa's shader cache while they run (gl/shader_cache.h: keep_shader_cache_in).
inline constexpr const char* kShaderCacheFolder = ".shader-cache";

// A shader cache on a full or unwritable disk is switched off first (Mesa
// would die of SIGBUS writing it), with a one-line note on stderr; a SIGBUS
// that still happens is reported (interrupt.h: report_bus_errors).
std::unique_ptr<HeadlessContext> make_headless_context(Backend backend);

}  // namespace m3055
