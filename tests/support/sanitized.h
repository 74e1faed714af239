// Whether this test binary is the sanitizer tree's (scripts/test-sanitize:
// clang with AddressSanitizer + UndefinedBehaviorSanitizer). Code there runs
// several times slower, so a few tests scale what they do by it, each saying why.
#pragma once

#include "io/sanitized_build.h"

namespace m3055::test {

inline constexpr bool kSanitized = kSanitizedBuild;

}  // namespace m3055::test
