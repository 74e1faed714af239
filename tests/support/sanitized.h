// Whether this test binary is the sanitizer tree's (scripts/test-sanitize:
// clang with AddressSanitizer + UndefinedBehaviorSanitizer). Code there runs
// several times slower, so a few tests scale what they do by it, each saying why.
#pragma once

namespace m3055::test {

#if defined(__SANITIZE_ADDRESS__)  // GCC
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)  // clang
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

}  // namespace m3055::test
