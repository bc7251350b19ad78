// What every reflection model shares: the shading frame (normalise N, L, E visibly; decide the
// horizon and the mirror side exactly on the raw vectors), the half vector and the mirror
// direction, and the listing lines of those steps (each model's listing includes them).
// Semantics: docs/lighting/semantics.md.
#pragma once
#include <cmath>
#include <optional>
#include <type_traits>
#include "core/exact_sign.hpp"
#include "core/functions.hpp"
#include "core/number.hpp"
#include "core/probe.hpp"
#include "lighting/brdf.hpp"

namespace sw::lighting {

// The frame's lines, first in every model's listing.
#define SW_LIGHTING_FRAME_LINES(X) \
  X(normalise, "n <- N/|N|; l <- L/|L|; e <- E/|E|       -- N, L, E as given, any length") \
  X(horizon, "lit <- N.L > 0; seen <- N.E > 0          -- exact signs of the raw dot products") \
  X(below, "if not (lit and seen): term <- 0; stop    -- light or eye behind the surface")

// The polynomials of the frame's exact decisions, generic over the number type (core/exact_sign.hpp
// evaluates them on its filter stages and in rationals).
// a.b
inline constexpr auto dot_polynomial = [](const auto& a, const auto& b) { return dot(a, b); };
// 2 (N.L)(N.E) - (N.N)(L.E): |N|^2 |L| |E| times r.e, with r the mirror of l about n.
inline constexpr auto mirror_polynomial = [](const auto& N, const auto& L, const auto& E) {
  using T = std::decay_t<decltype(N.x)>;
  return T(2) * dot(N, L) * dot(N, E) - dot(N, N) * dot(L, E);
};

// sign(a.b) and the mirror side of the raw vectors, exactly (num::exact_sign).
template <class Num> int sign_dot(const Vec3<Num>& a, const Vec3<Num>& b) { return num::exact_sign(dot_polynomial, a, b); }
template <class Num> int sign_mirror(const Vec3<Num>& n, const Vec3<Num>& l, const Vec3<Num>& e) {
  return num::exact_sign(mirror_polynomial, n, l, e);
}

// v / |v| (v != 0; a float v whose square underflows gives Inf or NaN components: a float failure
// the bench counts, never masked).
template <class Num> Vec3<Num> unit(const Vec3<Num>& v) { return (Num(1) / num::sqrt_of(dot(v, v))) * v; }

// The frame of raw N, L, E (non-zero), with its steps on listing L (which includes
// SW_LIGHTING_FRAME_LINES). `given`, if set, holds the decisions made beforehand on the exact input
// (the runtime does that, so that every mode takes the reference's branches even when rounding the
// input to float changes a sign); else they are made here, exactly on N, L, E as given.
struct FrameSigns {
  bool lit, seen, mirror;
};
template <class Num> FrameSigns frame_signs(const Vec3<Num>& N, const Vec3<Num>& L, const Vec3<Num>& E) {
  return {sign_dot(N, L) > 0, sign_dot(N, E) > 0, sign_mirror(N, L, E) > 0};
}

template <class L, NumberType Num, StepProbe Probe>
Frame<Num> shading_frame(const Vec3<Num>& N, const Vec3<Num>& Lv, const Vec3<Num>& E, Probe& probe,
                         const std::optional<FrameSigns>& given = std::nullopt) {
  Frame<Num> f;
  f.n = unit(N), f.l = unit(Lv), f.e = unit(E);
  if constexpr (Probe::on) {
    const Vec3<Num> o{};
    probe.step(L::normalise, StepKind::init)
        .vec("n", f.n)
        .vec("l", f.l)
        .vec("e", f.e)
        .segment(o, f.n)
        .label("n")
        .keep()
        .segment(o, f.l)
        .label("l")
        .keep()
        .segment(o, f.e)
        .label("e")
        .keep()
        .plane(o, f.n)
        .keep();  // the surface's tangent plane, for the 3D view
  }
  const FrameSigns s = given ? *given : frame_signs(N, Lv, E);
  f.lit = s.lit, f.seen = s.seen, f.mirror = s.mirror;
  f.nl = dot(f.n, f.l), f.ne = dot(f.n, f.e);
  if constexpr (Probe::on)
    probe.step(L::horizon, StepKind::decide).idx("lit", f.lit).idx("seen", f.seen).num("nl", f.nl).num("ne", f.ne);
  return f;
}

// h = (l + e)/|l + e|. Defined whenever lit and seen: n.l > 0 and n.e > 0 rule out l = -e.
template <class Num> Vec3<Num> half_vector(const Frame<Num>& f) { return unit(Vec3<Num>(f.l + f.e)); }
// r = 2 (n.l) n - l: the mirror direction of l about n (unit when n and l are).
template <class Num> Vec3<Num> mirror_of(const Frame<Num>& f) { return Num(2) * f.nl * f.n - f.l; }

// Runs a model's term on the frame: 0 below the horizon (the `below` step), else term().
template <class L, class Num, class Probe, class Term> Num frame_term(const Frame<Num>& f, Probe& probe, Term&& term) {
  if (!(f.lit && f.seen)) {
    if constexpr (Probe::on) probe.step(L::below, StepKind::done).num("term", Num(0));
    return Num(0);
  }
  return term();
}

}  // namespace sw::lighting
