// What the project's targets differ in, in one place. The browser build (emscripten 3.1.6, wasm32)
// has an older libc++: no std::bit_cast and no floating-point std::to_chars / std::from_chars; and
// on wasm32 a long has 32 bits, so GMP's functions that take or return a long cannot carry an int64.
// Each helper here is the standard call where the library has it; the fallbacks are compiled on
// every target, so the native tests check them against the standard calls (tests/test_portable.cpp).
#pragma once
#include <charconv>
#include <cstdint>
#include <string_view>
#include <gmpxx.h>

namespace sw {

template <class To, class From> constexpr To bit_cast(const From& from) noexcept { return __builtin_bit_cast(To, from); }

#if defined(__cpp_lib_to_chars) && !defined(__EMSCRIPTEN__)
#define SW_STD_FLOAT_CHARS 1
#else
#define SW_STD_FLOAT_CHARS 0
#endif

namespace portable {
// The shortest decimal text that reads back as x (ties: the one nearest x), in std::to_chars's
// plain format: fixed or scientific, whichever is shorter (fixed on a tie), "inf", "-inf", "nan".
// first must have room for 32 characters. Returns one past the text.
char* shortest_chars(char* first, double x);
char* shortest_chars(char* first, float x);
// The whole of s as a double by std::from_chars's rules (no leading space or '+'); false if it is not one.
bool parse_double(std::string_view s, double& out);
// An int64 to and from GMP through its bytes (mpz_import, mpz_export), where a long is too narrow.
mpz_class mpz_of(std::int64_t v);
std::int64_t int64_of(const mpz_class& z);
}  // namespace portable

// std::to_chars(first, last, x).ptr for a float or double, on every target.
template <class F> char* shortest_chars(char* first, [[maybe_unused]] char* last, F x) {
#if SW_STD_FLOAT_CHARS
  return std::to_chars(first, last, x).ptr;
#else
  return portable::shortest_chars(first, x);
#endif
}
// std::from_chars over the whole of s; false where it fails or leaves characters over.
inline bool parse_double(std::string_view s, double& out) {
#if SW_STD_FLOAT_CHARS
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size();
#else
  return portable::parse_double(s, out);
#endif
}

namespace num {
// An int64 as a GMP integer, and back (precondition: z fits in an int64), whatever a long holds.
inline mpz_class mpz_of(std::int64_t v) {
  if constexpr (sizeof(long) >= sizeof(std::int64_t)) return mpz_class(static_cast<long>(v));
  else return portable::mpz_of(v);
}
inline std::int64_t int64_of(const mpz_class& z) {
  if constexpr (sizeof(long) >= sizeof(std::int64_t)) return z.get_si();
  else return portable::int64_of(z);
}
}  // namespace num

}  // namespace sw
