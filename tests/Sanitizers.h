// Whether the tests run under AddressSanitizer (.ci/sanitize.sh), whose quarantine keeps freed
// memory resident: a bound on a process's peak memory holds only in the Release suite.
#pragma once

namespace tetglow::test {

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

}  // namespace tetglow::test
