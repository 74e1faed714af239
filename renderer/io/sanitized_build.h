#pragma once

// Whether this translation unit is built with a sanitizer that checks memory
// at exit or slows every allocation: AddressSanitizer (with LeakSanitizer),
// ThreadSanitizer or MemorySanitizer. GCC says so with __SANITIZE_*__, clang
// with __has_feature. A sanitized build must exit normally (LeakSanitizer's
// check runs then) and its memory limits differ.

namespace m3055 {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool kSanitizedBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif
#else
inline constexpr bool kSanitizedBuild = false;
#endif

}  // namespace m3055
