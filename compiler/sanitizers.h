// Which sanitizer this translation unit is compiled under, the same answer from GCC and clang:
// GCC defines __SANITIZE_ADDRESS__ / __SANITIZE_THREAD__; clang answers through
// __has_feature(address_sanitizer) / __has_feature(thread_sanitizer) instead. Code that sizes
// stacks or reserves for instrumented frames, or skips what a sanitizer's runtime cannot run,
// tests PF_UNDER_ASAN / PF_UNDER_TSAN / PF_SANITIZED.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define PF_UNDER_ASAN 1
#endif
#if defined(__SANITIZE_THREAD__)
#define PF_UNDER_TSAN 1
#endif
#if defined(__has_feature)
#if __has_feature(address_sanitizer) && !defined(PF_UNDER_ASAN)
#define PF_UNDER_ASAN 1
#endif
#if __has_feature(thread_sanitizer) && !defined(PF_UNDER_TSAN)
#define PF_UNDER_TSAN 1
#endif
#endif

#if defined(PF_UNDER_ASAN) || defined(PF_UNDER_TSAN)
#define PF_SANITIZED 1
#endif
