// The one bridge between the project's exact numbers and CGAL's, for the oracles' .cpp files:
// CGAL stays out of every header that runtime/ or algorithms/ include, so include this only from
// oracle/*.cpp.
#pragma once
#include <type_traits>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>
#include "core/number.hpp"
#include "core/vec.hpp"

namespace sw::oracle {

using Q = CGAL::Gmpq;
inline Q q(const Rational& v) { return Q(v.get_mpq_t()); }
inline Rational r(const Q& x) { return Rational(x.mpq()); }

// The kernel the oracles state their geometry in: CGAL's cartesian kernel on GMP rationals.
using ExactKernel = CGAL::Simple_cartesian<Q>;

// A point of kernel K. A kernel on doubles (Epick, for its filtered predicates) takes the
// coordinates as doubles: the caller has checked that they are (every input coordinate a double).
template <class K = ExactKernel> typename K::Point_2 point(const Vec2<Rational>& v) {
  if constexpr (std::is_same_v<typename K::FT, double>) return {v.x.get_d(), v.y.get_d()};
  else return {q(v.x), q(v.y)};
}
template <class K = ExactKernel> typename K::Point_3 point(const Vec3<Rational>& v) {
  if constexpr (std::is_same_v<typename K::FT, double>) return {v.x.get_d(), v.y.get_d(), v.z.get_d()};
  else return {q(v.x), q(v.y), q(v.z)};
}

}  // namespace sw::oracle
