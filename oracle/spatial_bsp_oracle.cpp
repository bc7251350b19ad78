#include "spatial_bsp_oracle.hpp"
#include <algorithm>
#include <utility>
#include "cgal_bridge.hpp"

namespace sw::oracle {
namespace {

using K = ExactKernel;
using P2 = K::Point_2;
using V2 = K::Vector_2;

int orient(const P2& p, const P2& r, const P2& s) { return static_cast<int>(CGAL::orientation(p, r, s)); }
int turn(const V2& u, const V2& v) { return static_cast<int>(CGAL::orientation(u, v)); }  // sign of u x v
std::string show(const Vec2<Rational>& p) { return "(" + p.x.get_str() + ", " + p.y.get_str() + ")"; }

// A fragment as the eye sees it: the directions to its ends, counterclockwise (u x v > 0), or
// edge-on (the eye on its line: a set of rays of zero measure).
struct Seen {
  P2 a, b;
  V2 u, v;
  bool edge_on = false;
};

// Is x in the half-open arc [u, v) (u x v > 0, so the arc is less than a half turn)?
bool in_arc(const V2& x, const V2& u, const V2& v) {
  const int ux = turn(u, x);
  if (ux == 0) return CGAL::sign(u * x) > 0;
  return ux > 0 && turn(x, v) > 0;
}

// The ray parameter t at which eye + t w meets the line of ab (w not parallel to it).
Q ray_t(const P2& eye, const V2& w, const P2& a, const P2& b) {
  const V2 d = b - a, e = a - eye;
  return (e.x() * d.y() - e.y() * d.x()) / (w.x() * d.y() - w.y() * d.x());
}

// Does i hide part of j? A direction w strictly inside both open arcs, if any, and i strictly
// nearer along it; segments whose interiors cross hide each other.
enum class Hides { no, nearer, crossing };
Hides hides(const P2& eye, const Seen& i, const Seen& j) {
  if (i.edge_on || j.edge_on) return Hides::no;
  V2 start, end;
  if (in_arc(j.u, i.u, i.v)) start = j.u;
  else if (in_arc(i.u, j.u, j.v)) start = i.u;
  else return Hides::no;  // the open arcs are disjoint
  end = turn(i.v, j.v) > 0 ? i.v : j.v;  // whichever end comes first counterclockwise from start
  const int ia = orient(i.a, i.b, j.a), ib = orient(i.a, i.b, j.b), ja = orient(j.a, j.b, i.a), jb = orient(j.a, j.b, i.b);
  if (ia * ib < 0 && ja * jb < 0) return Hides::crossing;  // the nearer one changes inside the overlap
  const V2 w = start + end;                                // strictly inside the overlap (start x end > 0)
  return ray_t(eye, w, i.a, i.b) < ray_t(eye, w, j.a, j.b) ? Hides::nearer : Hides::no;
}

}  // namespace

std::string fragments_cover(const std::vector<Seg2Q>& segs, const std::vector<FragmentQ>& frags) {
  std::vector<std::vector<std::pair<Rational, Rational>>> pieces(segs.size());
  for (std::size_t f = 0; f < frags.size(); ++f) {
    const FragmentQ& g = frags[f];
    const std::string at = "fragment " + std::to_string(f);
    if (g.seg < 0 || static_cast<std::size_t>(g.seg) >= segs.size()) return at + ": no segment " + std::to_string(g.seg);
    const Seg2Q& s = segs[static_cast<std::size_t>(g.seg)];
    const P2 sa = point(s.a), sb = point(s.b);
    if (orient(sa, sb, point(g.a)) != 0 || orient(sa, sb, point(g.b)) != 0)
      return at + " " + show(g.a) + "-" + show(g.b) + " is off the line of segment " + std::to_string(g.seg);
    if (g.a == g.b) return at + ": zero length at " + show(g.a);
    const Vec2<Rational> d = s.b - s.a;
    const int k = abs(d.x) >= abs(d.y) ? 0 : 1;  // the parameter along the axis the segment moves most
    const Rational ta = (g.a[k] - s.a[k]) / d[k], tb = (g.b[k] - s.a[k]) / d[k];
    pieces[static_cast<std::size_t>(g.seg)].emplace_back(std::min(ta, tb), std::max(ta, tb));
  }
  for (std::size_t s = 0; s < segs.size(); ++s) {
    auto& p = pieces[s];
    const std::string at = "segment " + std::to_string(s);
    if (p.empty()) return at + ": no fragment";
    std::sort(p.begin(), p.end());
    if (p.front().first != 0) return at + ": uncovered from its start to parameter " + p.front().first.get_str();
    for (std::size_t k = 1; k < p.size(); ++k) {
      if (p[k].first < p[k - 1].second) return at + ": fragments overlap at parameters " + p[k].first.get_str() + " to " + p[k - 1].second.get_str();
      if (p[k].first > p[k - 1].second) return at + ": a gap at parameters " + p[k - 1].second.get_str() + " to " + p[k].first.get_str();
    }
    if (p.back().second != 1) return at + ": uncovered from parameter " + p.back().second.get_str() + " to its end";
  }
  return "";
}

OrderCheck painter_order(const Vec2<Rational>& eye_q, const std::vector<FragmentQ>& frags, const std::vector<std::int32_t>& order) {
  OrderCheck out;
  std::vector<char> seen_once(frags.size(), 0);
  bool perm = order.size() == frags.size();
  for (std::int32_t f : order) {
    if (f < 0 || static_cast<std::size_t>(f) >= frags.size() || seen_once[static_cast<std::size_t>(f)]) perm = false;
    else seen_once[static_cast<std::size_t>(f)] = 1;
  }
  if (!perm) {
    out.violations = 1;
    out.first = "the order is not a permutation of the " + std::to_string(frags.size()) + " fragments";
    return out;
  }
  const P2 eye = point(eye_q);
  std::vector<Seen> seen;
  seen.reserve(order.size());
  for (std::int32_t f : order) {
    Seen s;
    s.a = point(frags[static_cast<std::size_t>(f)].a), s.b = point(frags[static_cast<std::size_t>(f)].b);
    const int o = orient(eye, s.a, s.b);
    s.edge_on = o == 0;
    s.u = s.a - eye, s.v = s.b - eye;
    if (o < 0) std::swap(s.u, s.v);
    seen.push_back(std::move(s));
  }
  for (std::size_t p = 0; p < seen.size(); ++p)
    for (std::size_t r = p + 1; r < seen.size(); ++r)
      if (const Hides h = hides(eye, seen[p], seen[r]); h != Hides::no) {
        out.crossings += h == Hides::crossing;
        if (out.violations++ == 0)
          out.first = "fragment " + std::to_string(order[p]) + " (drawn " + std::to_string(p) + ") hides part of fragment " +
                      std::to_string(order[r]) + " (drawn " + std::to_string(r) + ")";
      }
  return out;
}

}  // namespace sw::oracle
