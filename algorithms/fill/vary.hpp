// A point that carries what varies linearly across a triangle: its position and up to kMaxAttrs
// attribute values (a colour, texture coordinates, any list of numbers). The fills step it as one
// vector, as the implementor's guide does: q <- q + dq moves the position and every attribute.
#pragma once
#include <array>
#include <cstddef>
#include <span>
#include "core/vec.hpp"

namespace sw::fill {

inline constexpr std::size_t kMaxAttrs = 8;  // per input vertex
// Room for one more carried value than an input has: perspective-interp carries a/w and 1/w.

template <class Num> struct Vary {
  Vec2<Num> p;
  std::array<Num, kMaxAttrs + 1> a{};
  std::size_t n = 0;  // values in use

  std::span<const Num> attrs() const { return {a.data(), n}; }
  friend Vary operator+(const Vary& u, const Vary& v) {
    return zip(u, v, [](const Num& x, const Num& y) { return x + y; });
  }
  friend Vary operator-(const Vary& u, const Vary& v) {
    return zip(u, v, [](const Num& x, const Num& y) { return x - y; });
  }
  friend Vary operator*(const Num& s, const Vary& v) {
    return zip(v, v, [&](const Num& x, const Num&) { return s * x; });
  }
  friend Vary operator/(const Vary& v, const Num& s) {
    return zip(v, v, [&](const Num& x, const Num&) { return x / s; });
  }

 private:
  template <class F> static Vary zip(const Vary& u, const Vary& v, F f) {
    Vary r;
    r.n = u.n;
    r.p = {f(u.p.x, v.p.x), f(u.p.y, v.p.y)};
    for (std::size_t k = 0; k < u.n; ++k) r.a[k] = f(u.a[k], v.a[k]);
    return r;
  }
};

}  // namespace sw::fill
