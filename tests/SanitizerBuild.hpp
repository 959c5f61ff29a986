#pragma once

namespace abalike::test
{

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ABALIKE_TEST_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define ABALIKE_TEST_ASAN 1
#endif

/// True in the sanitizer build (tools/test's second stage). Sweeps over many generated inputs run fewer of them
/// there: the sanitizers look for memory and UB errors, which the first inputs reach as well as the rest, and the
/// Release build runs the full sweep.
#ifdef ABALIKE_TEST_ASAN
inline constexpr bool kSanitizerBuild = true;
#else
inline constexpr bool kSanitizerBuild = false;
#endif

} // namespace abalike::test
