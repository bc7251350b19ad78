// What the ray family's two catalog files share: the coordinate bound and the 3D point reader.
#pragma once
#include <array>
#include <cmath>
#include <string>
#include "input.hpp"

namespace sw {

namespace rays {

// Inputs beyond this are rejected: far enough for the far-sphere cases (1e8) and far origins,
// small enough that double products of a few coordinates cannot overflow.
inline constexpr double kCoordBound = 1e15;

// [x, y, z] within the bound; neg_zero, if given, records which components are a JSON -0.0.
inline Vec3<Rational> point3(const Json& j, const std::string& what, std::array<bool, 3>* neg_zero = nullptr) {
  if (!j.is_array() || j.size() != 3) throw InputError(what + ": expected an array of 3 numbers");
  Vec3<Rational> p;
  for (int k = 0; k < 3; ++k) {
    const std::string w = what + "[" + std::to_string(k) + "]";
    p[k] = parse_rational(j[k], w);
    check_bound(p[k], kCoordBound, w);
    if (neg_zero) (*neg_zero)[k] = j[k].is_number_float() && j[k].get<double>() == 0 && std::signbit(j[k].get<double>());
  }
  return p;
}

}  // namespace rays

}  // namespace sw
