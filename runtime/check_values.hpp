// How `check` compares one value of the replay with the trace's: the tolerance by the trace's mode,
// a cheap double filter before exact rationals, and the message a person reads. docs/trace-format.md.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include "input.hpp"

namespace sw::check_values {

// Readers and printers recurse at most this deep: a trace nested deeper is refused first.
inline constexpr std::size_t kMaxNesting = 64;

// How closely a trace's numbers must match the replay's. Integers (indices, flags) and decision
// geometry (pixels, spans) always match exactly; numbers within rel * (1 + |expected|).
struct Tolerance {
  Rational rel;         // 0: exactly
  bool numbers = true;  // false: --decisions-only, numbers are not compared
  double rel_d = rel.get_d();  // rel as a double (a power of 2), for the filter in value_diff
};

// A number's value as a double with a bound on its relative error, when it is cheap to get: a JSON
// number (exact), or a "p/q" / decimal string. Parts that read as finite doubles are rounded once
// each; longer parts (a reference value's thousands of digits) are read from their first 18
// digits and their length, so that a rounded trace is compared without exact arithmetic.
struct Approx {
  double value, rel;
};
// A string's value ("p/q", "n" or a short decimal), if it is cheap to get.
std::optional<Approx> approx_text(std::string_view s);
// The filter before exact rationals, as for the algorithms' own decisions: true where the values'
// difference is surely within the tolerance, their rounding counted against it; false where only
// the exact comparison can tell (and always for a tolerance below 2^-40).
bool surely_within(const Approx& want, const Approx& got, const Tolerance& tol);

// A value for a person: the text, and for rationals that are not integers "~ decimal" beside it.
std::string show(const Json& v);
// Compares the replay's value `want` with the trace's `got`; says what differs, or nothing. `exact`
// forces an exact comparison of numbers (integers, decision geometry).
std::optional<std::string> value_diff(const Json& want, const Json& got, const Tolerance& tol, bool exact, const std::string& path, std::size_t depth = 0);

}  // namespace sw::check_values
