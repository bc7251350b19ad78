#include "core/portable.hpp"
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>

namespace sw::portable {

namespace {

// A decimal p-digit significand N (as text) and the exponent E of its first digit: N[0].N[1..] x 10^E.
struct Decimal {
  bool negative = false;
  std::string digits;
  int exp = 0;
};

Decimal parse_scientific(const char* s) {  // "-d.ddde+XX" as printf's %e writes it
  Decimal d;
  if (*s == '-') d.negative = true, ++s;
  for (; *s && *s != 'e'; ++s)
    if (*s != '.') d.digits += *s;
  d.exp = std::atoi(s + 1);
  return d;
}

// The p-digit neighbours of d, one unit in its last digit away; below 10..0 the grid is ten times finer.
Decimal step(Decimal d, int dir) {
  std::string& n = d.digits;
  if (dir > 0) {
    int i = static_cast<int>(n.size()) - 1;
    for (; i >= 0 && n[i] == '9'; --i) n[i] = '0';
    if (i < 0) n.insert(n.begin(), '1'), n.pop_back(), ++d.exp;
    else ++n[i];
  } else if (n[0] == '1' && n.find_first_not_of('0', 1) == std::string::npos) {
    n.assign(n.size(), '9'), --d.exp;
  } else {
    int i = static_cast<int>(n.size()) - 1;
    for (; n[i] == '0'; --i) n[i] = '9';
    --n[i];
  }
  return d;
}

std::string scientific_text(const Decimal& d) {
  std::string t = d.negative ? "-" : "";
  t += d.digits[0];
  if (d.digits.size() > 1) t += '.', t.append(d.digits, 1);
  char e[16];
  std::snprintf(e, sizeof e, "e%c%02d", d.exp < 0 ? '-' : '+', std::abs(d.exp));
  return t + e;
}

// An integral value's fixed text is its exact digits, as printf's %.0f writes them (std::to_chars's
// rule: 2^62 is 4611686018427387904, not its 16 shortest digits and zeros); the digit count is the same.
std::string fixed_text(const Decimal& d, double x) {
  const std::string& n = d.digits;
  const int len = static_cast<int>(n.size());
  if (d.exp >= len - 1) {
    char exact[400];
    std::snprintf(exact, sizeof exact, "%.0f", x);
    return exact;
  }
  const std::string t = d.negative ? "-" : "";
  if (d.exp >= 0) return t + n.substr(0, static_cast<std::size_t>(d.exp) + 1) + "." + n.substr(static_cast<std::size_t>(d.exp) + 1);
  return t + "0." + std::string(static_cast<std::size_t>(-d.exp - 1), '0') + n;
}

template <class F> bool reads_back(const std::string& text, F x) {
  if constexpr (std::is_same_v<F, float>) return std::strtof(text.c_str(), nullptr) == x;
  else return std::strtod(text.c_str(), nullptr) == x;
}

template <class F> char* shortest(char* first, F x) {
  auto put = [&](const std::string& t) {
    std::memcpy(first, t.data(), t.size());
    return first + t.size();
  };
  if (std::isnan(x)) return put(std::signbit(x) ? "-nan" : "nan");
  if (std::isinf(x)) return put(x < 0 ? "-inf" : "inf");
  // The first precision at which the correctly rounded decimal, or (where the round-trip interval
  // is lopsided, at a power of two) one of its neighbours, reads back as x. Bounded: 17 digits
  // (9 for a float) always read back.
  constexpr int kMaxDigits = std::is_same_v<F, float> ? 9 : 17;
  Decimal found;
  for (int p = 1; p <= kMaxDigits; ++p) {
    char sci[48];
    std::snprintf(sci, sizeof sci, "%.*e", p - 1, static_cast<double>(x));
    const Decimal nearest = parse_scientific(sci);
    if (reads_back(scientific_text(nearest), x)) {
      found = nearest;
      break;
    }
    if (x == 0) continue;
    const Decimal up = step(nearest, 1), down = step(nearest, -1);
    if (reads_back(scientific_text(up), x)) {
      found = up;
      break;
    }
    if (reads_back(scientific_text(down), x)) {
      found = down;
      break;
    }
  }
  while (found.digits.size() > 1 && found.digits.back() == '0') found.digits.pop_back();
  const std::string fixed = fixed_text(found, static_cast<double>(x)), sci = scientific_text(found);
  return put(fixed.size() <= sci.size() ? fixed : sci);
}

}  // namespace

char* shortest_chars(char* first, double x) { return shortest(first, x); }
char* shortest_chars(char* first, float x) { return shortest(first, x); }

bool parse_double(std::string_view s, double& out) {
  if (s.empty() || s[0] == '+' || s[0] == ' ' || s[0] == '\t' || s[0] == '\n' || s[0] == '\r' || s[0] == '\f' || s[0] == '\v')
    return false;
  if (s.find_first_of("xX") != std::string_view::npos) return false;  // no hexadecimal in the general format
  const std::string text(s);
  char* end = nullptr;
  const double d = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return false;
  const bool inf_text = text.find_first_of("iI") != std::string::npos;
  if (std::isinf(d) && !inf_text) return false;  // out of range, as std::from_chars says
  if (d == 0 && text.find_first_of("123456789") < text.find_first_of("eE")) return false;  // underflow to 0
  out = d;
  return true;
}

mpz_class mpz_of(std::int64_t v) {
  const std::uint64_t m = v < 0 ? std::uint64_t(0) - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
  mpz_class z;
  mpz_import(z.get_mpz_t(), 1, 1, sizeof m, 0, 0, &m);
  if (v < 0) z = -z;
  return z;
}

std::int64_t int64_of(const mpz_class& z) {
  std::uint64_t m = 0;
  mpz_export(&m, nullptr, 1, sizeof m, 0, 0, z.get_mpz_t());  // |z| < 2^63: one word at most
  return sgn(z) < 0 ? static_cast<std::int64_t>(std::uint64_t(0) - m) : static_cast<std::int64_t>(m);
}

}  // namespace sw::portable
