// Whether this translation unit is built with AddressSanitizer. ASan reserves terabytes of address
// space for its shadow memory, so a child process under an address-space cap (RLIMIT_AS) could not
// allocate at all: sanitizer builds run such children without the cap.
#pragma once

namespace acd {

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

}  // namespace acd
