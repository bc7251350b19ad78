// How many generated cases a test runs. The sanitizer build runs the same assertions on a share of
// them: ASan and UBSan slow exact arithmetic 5-10x, and that job is there to find memory errors
// and undefined behaviour on every code path, which a smaller sample still reaches. The release
// build (scripts/test.sh) runs every case.
#pragma once
#include <algorithm>
#include <cstddef>

#if defined(__SANITIZE_ADDRESS__)
#define SW_TESTS_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SW_TESTS_SANITIZED 1
#endif
#endif

namespace sw::testing {

#ifdef SW_TESTS_SANITIZED
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
inline constexpr int kCaseShare = kSanitized ? 8 : 1;

// n generated cases in the release build, n / 8 (at least 1) under the sanitizers.
template <class I> constexpr I cases(I n) { return std::max(I{1}, static_cast<I>(n / kCaseShare)); }

// Whether the n-th of a stream of cases runs: every one in the release build, every 8th (the
// first always) under the sanitizers.
constexpr bool kept(std::size_t n) { return n % static_cast<std::size_t>(kCaseShare) == 0; }

}  // namespace sw::testing
