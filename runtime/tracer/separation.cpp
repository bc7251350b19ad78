#include "tracer/separation.hpp"
#include <algorithm>
#include <limits>

namespace sw::tracer::separation {

using Q = Rational;
using V = Vec3<Q>;

Q abs_q(const Q& x) { return x < 0 ? Q(-x) : x; }
Q norm1(const V& a) { return abs_q(a.x) + abs_q(a.y) + abs_q(a.z); }
bool is_zero(const V& v) { return sgn(v.x) == 0 && sgn(v.y) == 0 && sgn(v.z) == 0; }

std::vector<V> corners(const V& lo, const V& hi) {
  std::vector<V> c;
  for (int k = 0; k < 8; ++k) c.push_back({(k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z});
  return c;
}

std::optional<Proxy> proxy_of(const Scene& s, const Object& o) {
  Proxy p;
  switch (o.kind) {
    case Shape::sphere: {
      const V r{o.radius.q, o.radius.q, o.radius.q};
      p.pts = corners(o.a.q - r, o.a.q + r);
      break;
    }
    case Shape::box: p.pts = corners(o.a.q, o.b.q); break;
    case Shape::triangle:
      p.pts = {o.v[0].q, o.v[1].q, o.v[2].q};
      p.normal = cross(V(o.v[1].q - o.v[0].q), V(o.v[2].q - o.v[0].q)), p.has_normal = true;
      break;
    case Shape::plane:
      p.bounded = false, p.point = o.a.q, p.normal = o.b.q, p.has_normal = true;
      return p;
    case Shape::mesh: {
      const MeshFile& f = s.meshes[static_cast<std::size_t>(o.mesh)];
      if (!f.mesh || f.mesh->v.empty()) return std::nullopt;  // not loaded: no proof
      std::array<double, 3> lo{}, hi{};
      lo.fill(std::numeric_limits<double>::infinity()), hi.fill(-std::numeric_limits<double>::infinity());
      for (const auto& v : f.mesh->v)
        for (std::size_t k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
      V l, h;
      for (int k = 0; k < 3; ++k) {  // the placed box: scale * [lo, hi] + translate (scale > 0)
        l[k] = o.scale.q * Q(lo[static_cast<std::size_t>(k)]) + o.translate.q[k];
        h[k] = o.scale.q * Q(hi[static_cast<std::size_t>(k)]) + o.translate.q[k];
      }
      p.pts = corners(l, h);
      break;
    }
  }
  p.lo = p.hi = p.pts[0];
  for (const V& v : p.pts)
    for (int k = 0; k < 3; ++k) p.lo[k] = std::min(p.lo[k], v[k]), p.hi[k] = std::max(p.hi[k], v[k]);
  return p;
}

struct Interval1 {
  Q lo, hi;
  bool lo_inf = false, hi_inf = false;
};
Interval1 project(const std::vector<V>& pts, const V& a) {
  Interval1 r{dot(a, pts[0]), dot(a, pts[0])};
  for (const V& p : pts) {
    const Q x = dot(a, p);
    if (x < r.lo) r.lo = x;
    if (r.hi < x) r.hi = x;
  }
  return r;
}
// Disjoint with a gap wider than the margin on both sides.
bool apart(const Interval1& a, const Interval1& b, const Q& pad) {
  return (!a.hi_inf && !b.lo_inf && a.hi + 2 * pad < b.lo) || (!b.hi_inf && !a.lo_inf && b.hi + 2 * pad < a.lo);
}
V centre(const Proxy& p) { return Q(1, 2) * V(p.lo + p.hi); }
// The side of x relative to the plane (point, normal), with the margin: +1, -1, or 0 (too close).
int side(const Proxy& plane, const V& x, const Q& margin) {
  const Q v = dot(plane.normal, V(x - plane.point)), pad = margin * norm1(plane.normal);
  return v > pad ? 1 : v < -pad ? -1 : 0;
}
int side_all(const Proxy& plane, const std::vector<V>& pts, const Q& margin) {
  const int s0 = side(plane, pts[0], margin);
  for (const V& p : pts)
    if (side(plane, p, margin) != s0) return 0;
  return s0;
}

// Whether occluder b might lie between a point of receiver a and the light (a != b); false is a proof.
bool may_shadow(const Proxy& a, const Proxy& b, const LightAt& l, const Q& margin) {
  if (!a.bounded && !b.bounded) {
    if (!is_zero(cross(a.normal, b.normal))) return true;
    const int light_side = l.directional ? sgn(dot(a.normal, l.where)) : side(a, l.where, margin);
    return light_side == 0 || side(a, b.point, margin) != -light_side;
  }
  if (!a.bounded) {  // b must lie wholly on the far side of a's plane from the light
    const int light_side = l.directional ? sgn(dot(a.normal, l.where)) : side(a, l.where, margin);
    return light_side == 0 || side_all(a, b.pts, margin) != -light_side;
  }
  if (!b.bounded) {  // a and the whole way to the light on one side of b's plane
    const int sa = side_all(b, a.pts, margin);
    if (sa == 0) return true;
    return l.directional ? sgn(dot(b.normal, l.where)) * sa < 0 : side(b, l.where, margin) != sa;
  }
  std::vector<V> axes{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const V da = l.directional ? l.where : V(l.where - centre(a)), db = l.directional ? l.where : V(l.where - centre(b));
  for (int k = 0; k < 3; ++k) axes.push_back(cross(da, axes[static_cast<std::size_t>(k)])), axes.push_back(cross(db, axes[static_cast<std::size_t>(k)]));
  axes.push_back(da), axes.push_back(db), axes.push_back(cross(da, db));
  if (a.has_normal) axes.push_back(a.normal);
  if (b.has_normal) axes.push_back(b.normal);
  for (const V& ax : axes) {
    if (is_zero(ax)) continue;
    Interval1 ra = project(a.pts, ax);
    if (l.directional) {
      const int s = sgn(dot(ax, l.where));
      ra.hi_inf = s > 0, ra.lo_inf = s < 0;
    } else {
      const Q x = dot(ax, l.where);
      if (x < ra.lo) ra.lo = x;
      if (ra.hi < x) ra.hi = x;
    }
    if (apart(ra, project(b.pts, ax), margin * norm1(ax))) return false;
  }
  return true;
}

bool inside_or_on(const Object& o, const V& e) {
  if (o.kind == Shape::sphere) {
    const V f = e - o.a.q;
    return dot(f, f) <= o.radius.q * o.radius.q;
  }
  for (int k = 0; k < 3; ++k)
    if (e[k] < o.a.q[k] || e[k] > o.b.q[k]) return false;
  return true;
}

// A convex object shadows itself only where a ray reaches its inside, or a bump map tilts the normal.
bool may_self_shadow(const Scene& s, std::size_t k, const std::vector<std::optional<Proxy>>& px, const Q& margin) {
  const Object& o = s.objects[k];
  if (o.kind == Shape::plane || o.kind == Shape::triangle) return false;
  if (o.kind == Shape::mesh) return true;
  const Material& m = s.materials[static_cast<std::size_t>(o.material)];
  if (m.bump.on || sgn(m.kt.q) > 0 || inside_or_on(o, s.camera.eye.q)) return true;
  for (std::size_t j = 0; j < px.size(); ++j) {  // a mirror or glass reaching into it could send weighted rays inside
    const Material& mj = s.materials[static_cast<std::size_t>(s.objects[j].material)];
    if (j == k || (sgn(mj.kr.q) == 0 && sgn(mj.kt.q) == 0)) continue;
    if (!px[j]) return true;
    const Proxy& b = *px[j];
    const Proxy& a = *px[k];
    if (!b.bounded) {
      if (side_all(b, a.pts, margin) == 0) return true;
    } else {
      bool overlap = true;
      for (int c = 0; c < 3; ++c) overlap = overlap && !(b.hi[c] + 2 * margin < a.lo[c] || a.hi[c] + 2 * margin < b.lo[c]);
      if (overlap) return true;
    }
  }
  return false;
}

}  // namespace sw::tracer::separation
