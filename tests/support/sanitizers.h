#pragma once
// Whether the tests run under AddressSanitizer (a LUCERNA_SANITIZE build, README "Sanitizers"):
// ASan reserves terabytes of address space for its shadow (so no RLIMIT_AS can be set on a child),
// and its quarantine and redzones cost time and memory, so that the resource bounds the hostile-
// file tests put on a run are multiplied by kResourceScale there.

namespace lucerna::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kAddressSanitizer = true;
#else
inline constexpr bool kAddressSanitizer = false;
#endif
#else
inline constexpr bool kAddressSanitizer = false;
#endif

inline constexpr double kResourceScale = kAddressSanitizer ? 5.0 : 1.0;

}  // namespace lucerna::test
