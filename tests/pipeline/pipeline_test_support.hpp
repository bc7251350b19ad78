// Shared by the pipeline family's tests: reading an input's exact numbers straight from its JSON.
#pragma once
#include <string>
#include "core/number.hpp"
#include "core/vec.hpp"
#include "input.hpp"

namespace sw::testing::pipeline {

// An exact number of an input: a JSON number (a double, exactly) or a "p/q" string.
inline Rational q_of(const Json& v) {
  if (!v.is_string()) return num::to_rational(v.get<double>());
  Rational r(v.get<std::string>());
  r.canonicalize();
  return r;
}
inline Vec3<Rational> point_of(const Json& v) { return {q_of(v[0]), q_of(v[1]), q_of(v[2])}; }

}  // namespace sw::testing::pipeline
