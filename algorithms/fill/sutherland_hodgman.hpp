// Sutherland-Hodgman: a polygon clipped to a convex polygon, one clip edge at a time. Against each
// edge's closed inner half-plane, every subject edge s -> p keeps p when p is inside and adds the
// point where it crosses the edge's line when s and p lie strictly on opposite sides.
// Semantics (the result compared as a region, by winding numbers): docs/fill/clipping.md.
#pragma once
#include <span>
#include <string_view>
#include <utility>
#include <vector>
#include "core/number.hpp"
#include "core/probe.hpp"
#include "core/vec.hpp"

namespace sw::fill {

struct SutherlandHodgman {
  static constexpr std::string_view id = "sutherland-hodgman";
  static constexpr std::string_view summary = "Sutherland-Hodgman: clip a polygon to a convex polygon, edge by edge";
#define SW_FILL_SUTHERLAND_HODGMAN(X) \
  X(orient, "o <- sign of the clip polygon's area        -- +1 counter-clockwise, -1 clockwise") \
  X(edges, "for each clip edge c_k -> c_k+1:") \
  X(edge, "    in <- out; out <- []; d(v) = o (c_k+1 - c_k) x (v - c_k)   -- v inside: d(v) >= 0") \
  X(vertices, "    for each edge s -> p of in (s before p, cyclically):") \
  X(side, "        d_s <- d(s); d_p <- d(p)") \
  X(cross, "        if d_s < 0 < d_p or d_p < 0 < d_s: emit s + d_s / (d_s - d_p) (p - s)   -- crosses the line") \
  X(keep, "        if d_p >= 0: emit p") \
  X(empty, "    if out is empty: return []                -- nothing is left inside") \
  X(clipped, "    show out: the subject clipped by edges 0 .. k") \
  X(done, "return out")
  SW_LISTING("Sutherland-Hodgman polygon clipping", SW_FILL_SUTHERLAND_HODGMAN)
#undef SW_FILL_SUTHERLAND_HODGMAN
};

// d(v) for the clip edge a -> b with orientation o: o times the cross product (b - a) x (v - a).
template <class Num> Num inner_side(const Num& o, const Vec2<Num>& a, const Vec2<Num>& b, const Vec2<Num>& v) {
  return o * ((b.x - a.x) * (v.y - a.y) - (b.y - a.y) * (v.x - a.x));
}

// Clips `subject` (any closed polygon, at least one vertex) to `clip` (convex, winding once, either
// orientation, at least three vertices; the caller checks). Returns the clipped polygon: empty, or
// its vertices in the subject's orientation.
template <NumberType Num, StepProbe Probe = NoProbe>
std::vector<Vec2<Num>> sutherland_hodgman(const std::vector<Vec2<Num>>& subject, const std::vector<Vec2<Num>>& clip,
                                          Probe& probe) {
  using L = SutherlandHodgman;
  const std::size_t m = clip.size();
  Num twice_area(0);
  for (std::size_t k = 0; k < m; ++k) {
    const Vec2<Num>& a = clip[k];
    const Vec2<Num>& b = clip[(k + 1) % m];
    twice_area = twice_area + (a.x * b.y - a.y * b.x);
  }
  const int o_sign = twice_area < Num(0) ? -1 : 1;  // a rounded area of 0 counts as counter-clockwise
  const Num o(o_sign);
  if constexpr (Probe::on) {
    probe.step(L::orient, StepKind::init).num("area2", twice_area).idx("o", o_sign);
    probe.geo_list(GeoKind::polygon, std::span<const Vec2<Num>>(clip)).label("clip").keep();
    probe.geo_list(GeoKind::polygon, std::span<const Vec2<Num>>(subject)).label("subject").keep();
  }
  std::vector<Vec2<Num>> in, out = subject;
  for (std::size_t k = 0; k < m; ++k) {
    const Vec2<Num>& a = clip[k];
    const Vec2<Num>& b = clip[(k + 1) % m];
    std::swap(in, out);
    out.clear();
    if constexpr (Probe::on)
      probe.step(L::edge, StepKind::advance).idx("k", static_cast<std::int64_t>(k)).segment(a, b).label("clip edge").replace();
    const Vec2<Num>* s = &in.back();
    Num d_s = inner_side(o, a, b, *s);
    for (const Vec2<Num>& p : in) {
      const Num d_p = inner_side(o, a, b, p);
      if constexpr (Probe::on)
        probe.step(L::side, StepKind::decide).num("d_s", d_s).num("d_p", d_p).point(p).label("p").value(d_p);
      if ((d_s < Num(0) && Num(0) < d_p) || (d_p < Num(0) && Num(0) < d_s)) {
        const Num t = d_s / (d_s - d_p);
        out.push_back(*s + t * (p - *s));
        if constexpr (Probe::on) probe.step(L::cross, StepKind::plot).num("t", t).point(out.back()).label("crossing");
      }
      if (!(d_p < Num(0))) {
        out.push_back(p);
        if constexpr (Probe::on) probe.step(L::keep, StepKind::plot).point(p).label("kept");
      }
      s = &p, d_s = d_p;
    }
    if (out.empty()) {
      if constexpr (Probe::on) probe.step(L::empty, StepKind::miss).idx("k", static_cast<std::int64_t>(k));
      return out;
    }
    if constexpr (Probe::on)
      probe.step(L::clipped, StepKind::advance)
          .idx("k", static_cast<std::int64_t>(k))
          .idx("n", static_cast<std::int64_t>(out.size()))
          .geo_list(GeoKind::polygon, std::span<const Vec2<Num>>(out))
          .label("clipped")
          .replace();
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("n", static_cast<std::int64_t>(out.size()));
  return out;
}

}  // namespace sw::fill
