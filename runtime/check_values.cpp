#include "check_values.hpp"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string_view>
#include <system_error>

namespace sw::check_values {

namespace {

// A run of digits as lead * 10^exp, lead its first 18 digits (exact in a long double).
struct Digits {
  long double lead;
  std::ptrdiff_t exp;
};
std::optional<Digits> approx_part(std::string_view s) {
  if (s.empty() || s.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  s.remove_prefix(std::min(s.find_first_not_of('0'), s.size() - 1));  // leading zeros would hide the leading digits
  constexpr std::size_t kLead = 18;
  const std::size_t n = std::min(s.size(), kLead);
  char lead[kLead + 1] = {};
  s.copy(lead, n);
  return Digits{std::strtold(lead, nullptr), static_cast<std::ptrdiff_t>(s.size() - n)};
}

}  // namespace

std::optional<Approx> approx_text(std::string_view s) {
  if (s.find_first_not_of("0123456789+-./") != std::string_view::npos) return std::nullopt;  // parse_rational's syntax decides
  const std::size_t slash = s.find('/');
  if (slash == std::string_view::npos && s.find('.') != std::string_view::npos) {  // a decimal: short ones only
    if (s.size() > 40) return std::nullopt;
    double d = 0;
    if (!parse_double(s, d) || !std::isfinite(d)) return std::nullopt;
    return Approx{d, 0x1p-52};
  }
  const bool negative = !s.empty() && s[0] == '-';
  const std::size_t start = !s.empty() && (s[0] == '-' || s[0] == '+');
  const auto p = approx_part(s.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start));
  const auto q = slash == std::string_view::npos ? std::optional<Digits>(Digits{1, 0}) : approx_part(s.substr(slash + 1));
  if (!p || !q || q->lead == 0) return std::nullopt;
  const std::ptrdiff_t e = p->exp - q->exp;
  if (e > 400 || e < -400) return std::nullopt;
  const long double x = p->lead / q->lead * std::pow(10.0L, static_cast<long double>(e));
  if (!(std::fabs(x) <= static_cast<long double>(std::numeric_limits<double>::max()))) return std::nullopt;  // a cast beyond double is undefined
  const double d = static_cast<double>(x);
  // Each part within 10^-17 of its value (18 digits kept), the long double steps within 2^-62, one
  // rounding to double: together below 2^-51.
  return Approx{negative ? -d : d, 0x1p-51};
}

bool surely_within(const Approx& w, const Approx& g, const Tolerance& tol) {
  if (tol.rel_d < 0x1p-40 || !std::isfinite(w.value) || !std::isfinite(g.value)) return false;
  const double err = (w.rel + 0x1p-52) * std::fabs(w.value) + (g.rel + 0x1p-52) * std::fabs(g.value);
  return std::fabs(g.value - w.value) + err <= tol.rel_d * (1 + std::fabs(w.value)) * (1 - 0x1p-50);
}

namespace {

std::optional<Approx> approx(const Json& v) {
  if (v.is_number()) return Approx{v.get<double>(), 0};
  if (!v.is_string()) return std::nullopt;
  return approx_text(v.get_ref<const std::string&>());
}

}  // namespace

// A value for a person: the text, and for rationals that are not integers "~ decimal" beside it.
std::string show(const Json& v) {
  std::string text = v.is_string() ? v.get<std::string>() : v.dump();
  if (text.size() > 80) text = text.substr(0, 77) + "...";
  try {
    const Rational q = parse_rational(v, "", kMaxExactTextChars);
    if (q.get_den() != 1 || v.is_string()) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.9g", q.get_d());
      if (text != buf) text += std::string(" (~ ") + buf + ")";
    }
  } catch (const InputError&) {
  }
  return text;
}

// Compares the replay's value `want` with the trace's `got`; says what differs, or nothing. `exact`
// forces an exact comparison of numbers (integers, decision geometry).
std::optional<std::string> value_diff(const Json& want, const Json& got, const Tolerance& tol, bool exact, const std::string& path, std::size_t depth) {
  auto differ = [&](const std::string& why) { return std::optional<std::string>(path + ": " + why); };
  if (depth > kMaxNesting) return differ("nested too deeply");
  const bool wn = want.is_number() || want.is_string(), gn = got.is_number() || got.is_string();
  if (wn && gn) {
    if (!exact && !tol.numbers && !want.is_number_integer()) return std::nullopt;  // --decisions-only
    // A filter, as for the algorithms' own decisions: where the difference of the double values is
    // surely within the tolerance (their rounding, at most 2^-51 relative each, counted against it),
    // the exact comparison is not needed. Rounded traces are mostly decided here.
    if (!exact && !want.is_number_integer()) {
      const auto w = approx(want), g = approx(got);
      if (w && g && surely_within(*w, *g, tol)) return std::nullopt;
    }
    Rational w, g;
    try {
      w = parse_rational(want, path, kMaxExactTextChars), g = parse_rational(got, path, kMaxExactTextChars);
    } catch (const InputError&) {
      return want == got ? std::nullopt : differ("expected " + show(want) + ", got " + show(got));
    }
    if (w == g || (!exact && !want.is_number_integer() && tol.rel > 0 && abs(Rational(g - w)) <= tol.rel * (1 + abs(w)))) return std::nullopt;
    std::string why = "expected " + show(want) + ", got " + show(got);
    if (!exact && tol.rel > 0) why += " (beyond the tolerance " + show(Json(tol.rel.get_str())) + " x (1 + |expected|))";
    return differ(why);
  }
  if (want.is_array() && got.is_array()) {
    if (want.size() != got.size()) return differ("expected " + std::to_string(want.size()) + " entries, got " + std::to_string(got.size()));
    for (std::size_t i = 0; i < want.size(); ++i)
      if (auto d = value_diff(want[i], got[i], tol, exact, path + "[" + std::to_string(i) + "]", depth + 1)) return d;
    return std::nullopt;
  }
  if (want.is_object() && got.is_object()) {
    for (auto it = want.begin(); it != want.end(); ++it) {
      if (it.key() == "fallback") continue;  // informational
      if (!got.contains(it.key())) return differ("missing \"" + it.key() + "\"");
      if (auto d = value_diff(*it, got[it.key()], tol, exact, path + "." + it.key(), depth + 1)) return d;
    }
    for (auto it = got.begin(); it != got.end(); ++it)
      if (it.key() != "fallback" && !want.contains(it.key())) return differ("unexpected \"" + it.key() + "\"");
    return std::nullopt;
  }
  return want == got ? std::nullopt : differ("expected " + show(want) + ", got " + show(got));
}

}  // namespace sw::check_values
