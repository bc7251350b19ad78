// The implicit-curve walk (the guide's section on implicit curves, in its midpoint form): follow
// the level set P(x, y) = 0 of a polynomial of degree <= 3 pixel by pixel. At each pixel the
// gradient picks the direction (the tangent's major axis) and the two candidates, an axial pixel A
// and a diagonal pixel D; the sign of P at their midpoint M picks one. P(M) is not evaluated
// afresh: a table of the mixed forward differences of P, on the lattice of half-integers, follows
// M with additions only. Semantics, tie rules and stopping rules: docs/curves/implicit.md.
#pragma once
#include <array>
#include <cstdint>
#include <string_view>
#include <unordered_set>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::curves {

// P(x, y) = sum c[i][j] x^i y^j, walked from the pixel `start` for at most max_steps moves.
// Entries with i + j > 3 are 0; degree is the largest i + j of a nonzero coefficient (>= 1).
// Preconditions (validated in runtime/curves/specs.cpp): 1 <= max_steps <= 2^20, |start| <= 2^20,
// |P| <= 2^100 on the box the walk can reach (so float never overflows).
template <class Num> struct ImplicitPoly {
  std::array<std::array<Num, 4>, 4> c{};
  Pixel start;
  std::int64_t max_steps = 1;
  int degree = 1;
};

// Why the walk stopped; the done step records the code as idx "stopped".
enum class WalkStop : std::uint8_t { closed, max_steps, singular, revisit };
inline constexpr std::array<std::string_view, 4> kWalkStopNames = {"closed", "max_steps", "singular", "revisit"};
// steps: the moves decided. A move onto the start (closed) or onto another plotted pixel (revisit)
// counts but plots nothing.
struct WalkEnd {
  WalkStop stopped = WalkStop::max_steps;
  std::int64_t steps = 0;
};

struct PixelHash {
  std::size_t operator()(const Pixel& p) const {
    return static_cast<std::size_t>(static_cast<std::uint64_t>(p.x) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(p.y));
  }
};

inline std::int64_t& pixel_axis(Pixel& p, int axis) { return axis == 0 ? p.x : p.y; }

// grad P at the pixel p, by direct evaluation of the two derivative polynomials.
template <class Num> Vec2<Num> implicit_gradient(const ImplicitPoly<Num>& P, Pixel p) {
  const Num x(p.x), y(p.y);
  const std::array<Num, 3> xp{Num(1), x, x * x}, yp{Num(1), y, y * y};
  Vec2<Num> g{Num(0), Num(0)};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; i + j < 4; ++j) {
      if (i > 0) g.x = g.x + Num(i) * P.c[i][j] * (xp[i - 1] * yp[j]);
      if (j > 0) g.y = g.y + Num(j) * P.c[i][j] * (xp[i] * yp[j - 1]);
    }
  return g;
}

// Q(u, v) = P(u/2, v/2), directly: used only to start the difference table.
template <class Num> Num implicit_q(const ImplicitPoly<Num>& P, std::int64_t u, std::int64_t v) {
  const Num half = Num(1) / Num(2), x = Num(u) * half, y = Num(v) * half;
  std::array<Num, 4> xp{Num(1)}, yp{Num(1)};
  for (int k = 1; k < 4; ++k) xp[k] = xp[k - 1] * x, yp[k] = yp[k - 1] * y;
  Num s(0);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; i + j < 4; ++j) s = s + P.c[i][j] * (xp[i] * yp[j]);
  return s;
}

// The mixed forward differences d[m][n] = (Du^m Dv^n Q)(u, v), m + n <= 3, at the probe point
// (u, v) of the doubled lattice; Du Q(u, v) = Q(u + 1, v) - Q(u, v). Q has degree <= 3, so the
// entries with m + n = 3 are constants and those with m + n = 4 are 0 (never stored).
template <class Num> struct DiffTable {
  std::array<std::array<Num, 4>, 4> d{};
  std::int64_t u = 0, v = 0;

  // By direct evaluation at the ten corners (u + i, v + j), i + j <= 3, then differenced in place:
  // along u in each row (the last entries first, so each subtracts its old left neighbour), then
  // along v in each column. Afterwards d[m][n] = Du^m Dv^n Q(u, v).
  static DiffTable at(const ImplicitPoly<Num>& P, std::int64_t u, std::int64_t v) {
    DiffTable t;
    t.u = u, t.v = v;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; i + j < 4; ++j) t.d[i][j] = implicit_q(P, u + i, v + j);
    for (int j = 0; j < 4; ++j)
      for (int m = 1; m + j < 4; ++m)
        for (int i = 3 - j; i >= m; --i) t.d[i][j] = t.d[i][j] - t.d[i - 1][j];
    for (int m = 0; m < 4; ++m)
      for (int n = 1; m + n < 4; ++n)
        for (int j = 3 - m; j >= n; --j) t.d[m][j] = t.d[m][j] - t.d[m][j - 1];
    return t;
  }
  // One unit step along axis (0: u, 1: v) in direction s = +1 or -1. With e the step's unit
  // vector, D the difference along it and X any entry, X(q + e) = X(q) + (D X)(q) and
  // X(q - e) = X(q) - (D X)(q - e). Stepping +1, the lower orders go first, so each adds the next
  // order's old value (at q); stepping -1, the higher orders go first, so each subtracts the next
  // order's new value (at q - e). The constant top orders never change.
  void step(int axis, int s) {
    for (int k = 0; k < 3; ++k) {  // k: the order along the other axis
      const int top = 2 - k;       // entries of order 0 .. top along the axis have a next order
      auto at = [&](int m) -> Num& { return axis == 0 ? d[m][k] : d[k][m]; };
      if (s > 0)
        for (int m = 0; m <= top; ++m) at(m) = at(m) + at(m + 1);
      else
        for (int m = top; m >= 0; --m) at(m) = at(m) - at(m + 1);
    }
    (axis == 0 ? u : v) += s;
  }
  // To (tu, tv) by unit steps; from one midpoint to the next that is at most 6 per axis.
  void move_to(std::int64_t tu, std::int64_t tv) {
    while (u != tu) step(0, u < tu ? 1 : -1);
    while (v != tv) step(1, v < tv ? 1 : -1);
  }
};

struct ImplicitCurve {
  static constexpr std::string_view id = "implicit-curve";
  static constexpr std::string_view summary =
      "Walks P(x, y) = 0 (degree <= 3) pixel by pixel, P at midpoints from mixed forward differences";
  // clang-format off
#define SW_LINES_IMPLICIT_CURVE(X)                                                                                           \
  X(start, "p <- start; k <- 0                       -- k counts the moves")                                                 \
  X(grad, "while k < max_steps: g <- grad P(p)     -- g = 0: stop (singular)")                                               \
  X(axes, "    t <- (-g_y, g_x); a <- larger |t_a| (tie: x iff t_x t_y < 0); s_a <- sign t_a; s_b <- sign t_b (0: -sign g_b)")\
  X(table, "    once: Q_mn <- differences of Q(u, v) = P(u/2, v/2) at (u, v) = 2M, M = p + s_a e_a + s_b e_b / 2")           \
  X(probe, "    (u, v) -> 2M by unit steps: +1: Q_mn += Q_m+1,n low m first; -1: Q_mn -= Q_m+1,n high m first")              \
  X(decide, "    diagonal <- Q_00 s_b g_b < 0          -- Q_00 = P(M); 0 keeps the axial pixel")                             \
  X(move, "    p <- p + s_a e_a (+ s_b e_b if diagonal); k <- k + 1; stop if p = start (closed) or plotted (revisit)")       \
  X(plot, "    plot p")                                                                                                      \
  X(done, "done                                    -- stopped: 0 closed, 1 max_steps, 2 singular, 3 revisit")
  SW_LISTING("Implicit curve by mixed forward differences", SW_LINES_IMPLICIT_CURVE)
#undef SW_LINES_IMPLICIT_CURVE
  // clang-format on
};

template <NumberType Num, StepProbe Probe = NoProbe>
WalkEnd implicit_curve(const ImplicitPoly<Num>& P, std::vector<Pixel>& out, Probe& probe) {
  using L = ImplicitCurve;
  Pixel p = P.start;
  std::unordered_set<Pixel, PixelHash> plotted{p};
  out.push_back(p);
  if constexpr (Probe::on) {
    probe.step(L::start, StepKind::init).idx("degree", P.degree).idx("x", p.x).idx("y", p.y);
    probe.step(L::plot, StepKind::plot).pixel(p);
  }
  DiffTable<Num> T;
  bool have_table = false;
  WalkEnd end;
  while (end.steps < P.max_steps) {  // bounded: every pass moves once or stops
    const Vec2<Num> g = implicit_gradient(P, p);
    const bool singular = g.x == Num(0) && g.y == Num(0);
    if constexpr (Probe::on) probe.step(L::grad, StepKind::visit).idx("x", p.x).idx("y", p.y).num("gx", g.x).num("gy", g.y);
    if (singular) {
      end.stopped = WalkStop::singular;
      break;
    }
    // Walking along t, P < 0 lies on the left. a: 0 = x, 1 = y.
    const Vec2<Num> t{-g.y, g.x};
    const Num ax = num::abs(t.x), ay = num::abs(t.y);
    const int a = ax > ay || (!(ay > ax) && num::sign(t.x) != num::sign(t.y)) ? 0 : 1, b = 1 - a;
    const int sa = num::sign(t[a]), sgb = num::sign(g[b]);
    const int sb = num::sign(t[b]) != 0 ? num::sign(t[b]) : -sgb;
    if constexpr (Probe::on) probe.step(L::axes, StepKind::decide).idx("major", a).idx("sa", sa).idx("sb", sb);
    // The probe point 2M = 2p + 2 s_a e_a + s_b e_b on the doubled lattice.
    Pixel m2{2 * p.x, 2 * p.y};
    pixel_axis(m2, a) += 2 * sa;
    pixel_axis(m2, b) += sb;
    [[maybe_unused]] const auto half = [](std::int64_t w) { return Num(w) / Num(2); };  // x = u / 2
    if (!have_table) {
      T = DiffTable<Num>::at(P, m2.x, m2.y);
      have_table = true;
      if constexpr (Probe::on) {
        static constexpr const char* kQ[4][4] = {
            {"Q00", "Q01", "Q02", "Q03"}, {"Q10", "Q11", "Q12", ""}, {"Q20", "Q21", "", ""}, {"Q30", "", "", ""}};
        auto& st = probe.step(L::table, StepKind::init).idx("u", T.u).idx("v", T.v);
        for (int m = 0; m < 4; ++m)
          for (int n = 0; m + n < 4; ++n) st.num(kQ[m][n], T.d[m][n]);
        st.point(Vec2<Num>{half(T.u), half(T.v)});
      }
    } else {
      T.move_to(m2.x, m2.y);
      if constexpr (Probe::on)
        probe.step(L::probe, StepKind::advance)
            .idx("u", T.u)
            .idx("v", T.v)
            .num("PM", T.d[0][0])
            .point(Vec2<Num>{half(T.u), half(T.v)});
    }
    const bool diagonal = num::sign(T.d[0][0]) * sb * sgb < 0;
    if constexpr (Probe::on)  // the midpoint, coloured by the sign of P there that decides
      probe.step(L::decide, StepKind::decide)
          .num("PM", T.d[0][0])
          .idx("diagonal", diagonal)
          .point(Vec2<Num>{half(T.u), half(T.v)})
          .label("P(M)")
          .value(T.d[0][0]);
    Pixel next = p;
    pixel_axis(next, a) += sa;
    if (diagonal) pixel_axis(next, b) += sb;
    ++end.steps;
    if constexpr (Probe::on) probe.step(L::move, StepKind::advance).idx("x", next.x).idx("y", next.y).idx("k", end.steps);
    if (next == P.start) {
      end.stopped = WalkStop::closed;
      break;
    }
    if (!plotted.insert(next).second) {
      end.stopped = WalkStop::revisit;
      break;
    }
    p = next;
    out.push_back(p);
    if constexpr (Probe::on) probe.step(L::plot, StepKind::plot).pixel(p);
  }
  if constexpr (Probe::on)
    probe.step(L::done, StepKind::done).idx("stopped", static_cast<int>(end.stopped)).idx("steps", end.steps);
  return end;
}

}  // namespace sw::curves
