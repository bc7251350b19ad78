// The browser build's fallbacks (core/portable.hpp) against the standard calls they stand in for,
// which this (native) library has: the same text for every double and float tried, the same
// parse, and int64 values through GMP's bytes as through a long.
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>
#include "core/number.hpp"

using namespace sw;

namespace {

template <class F> std::string standard_text(F x) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}
template <class F> std::string portable_text(F x) {
  char buf[64];
  return std::string(buf, portable::shortest_chars(buf, x));
}

// Doubles of every kind: random bit patterns (every exponent), powers of two and their neighbours
// (where the round-trip interval is lopsided), integers, short decimals, the extremes.
template <class F> std::vector<F> samples() {
  using Bits = std::conditional_t<std::is_same_v<F, float>, std::uint32_t, std::uint64_t>;
  std::vector<F> v;
  std::mt19937_64 rng(29);
  for (int i = 0; i < 200000; ++i) {
    const F x = sw::bit_cast<F>(static_cast<Bits>(rng()));
    if (std::isfinite(x)) v.push_back(x);
  }
  for (int e = std::numeric_limits<F>::min_exponent - std::numeric_limits<F>::digits; e < std::numeric_limits<F>::max_exponent; ++e) {
    const F p = std::ldexp(F(1), e);
    v.insert(v.end(), {p, std::nextafter(p, F(0)), std::nextafter(p, std::numeric_limits<F>::infinity()), -p});
  }
  for (int i = -2000; i <= 2000; ++i) v.insert(v.end(), {F(i), F(i) / F(10), F(i) / F(1000), F(i) * F(1e6)});
  v.insert(v.end(), {F(0), -F(0), std::numeric_limits<F>::max(), std::numeric_limits<F>::min(), std::numeric_limits<F>::denorm_min(),
                     std::numeric_limits<F>::lowest(), F(0.1), F(1) / F(3), F(1e21), F(1e22), F(1e-7), F(123456789)});
  return v;
}

}  // namespace

TEST_CASE("portable: the shortest text of a double and a float is std::to_chars's", "[portable]") {
  std::size_t differ = 0, n = 0;
  for (double x : samples<double>()) {
    const std::string s = standard_text(x), p = portable_text(x);
    if (s != p && differ++ < 5) FAIL_CHECK(s << " written " << p);
    ++n;
  }
  for (float x : samples<float>()) {
    const std::string s = standard_text(x), p = portable_text(x);
    if (s != p && differ++ < 5) FAIL_CHECK(s << " (float) written " << p);
    ++n;
  }
  INFO(n << " values");
  CHECK(differ == 0);
  CHECK(n > 400000);
  CHECK(portable_text(std::numeric_limits<double>::infinity()) == standard_text(std::numeric_limits<double>::infinity()));
  CHECK(portable_text(-std::numeric_limits<double>::infinity()) == standard_text(-std::numeric_limits<double>::infinity()));
  CHECK(portable_text(std::numeric_limits<double>::quiet_NaN()) == standard_text(std::numeric_limits<double>::quiet_NaN()));
}

TEST_CASE("portable: a text reads as a double where std::from_chars reads it, to the same value", "[portable]") {
  std::vector<std::string> texts = {"0", "-0", "1", "-1.5", "0.1", "1e10", "1E-10", "2.5e+3", "1e400", "-1e400", "1e-400",
                                    "4.9e-324", "2.2250738585072014e-308", "+1", " 1", "1 ", "", "-", ".5", "5.", "0x10",
                                    "1e", "1e+", "inf", "-inf", "nan", "12abc", "00012", "9007199254740993",
                                    "0.30000000000000004", "1.7976931348623157e308", "1.7976931348623159e308"};
  std::mt19937_64 rng(3);
  for (int i = 0; i < 20000; ++i) texts.push_back(standard_text(sw::bit_cast<double>(rng())));
  for (const std::string& t : texts) {
    double a = 0, b = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), a);
    const bool standard = ec == std::errc() && end == t.data() + t.size();
    const bool mine = portable::parse_double(t, b);
    INFO("'" << t << "'");
    CHECK(mine == standard);
    if (mine && standard) CHECK((std::isnan(a) ? std::isnan(b) : sw::bit_cast<std::uint64_t>(a) == sw::bit_cast<std::uint64_t>(b)));
  }
}

TEST_CASE("portable: an int64 goes to GMP and back through its bytes as through a long", "[portable]") {
  std::vector<std::int64_t> v = {0, 1, -1, 42, -42, std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::min(),
                                 std::int64_t(1) << 31, -(std::int64_t(1) << 31), (std::int64_t(1) << 32) + 7, std::int64_t(1) << 53};
  std::mt19937_64 rng(11);
  for (int i = 0; i < 10000; ++i) v.push_back(static_cast<std::int64_t>(rng()) >> (rng() % 64));
  for (std::int64_t x : v) {
    INFO(x);
    CHECK(portable::mpz_of(x) == mpz_class(static_cast<long>(x)));
    CHECK(portable::int64_of(mpz_class(static_cast<long>(x))) == x);
    // Rational from a long long (the browser's int64) is the same number as from a long.
    const Rational q(static_cast<long long>(x));
    CHECK(q == Rational(static_cast<long>(x)));
    CHECK((q < static_cast<long long>(x) + (x < std::numeric_limits<std::int64_t>::max())) == (x < std::numeric_limits<std::int64_t>::max()));
    CHECK(num::floor_int(Rational(q + Rational(1, 3))) == x);
  }
}
