// Typed geometry emitters shared by the probes: each names the kind and its values' order once
// (SW_GEO_KINDS in step.hpp), so an algorithm writes probe.segment(a, b).label("chord").
// Self provides geo(GeoKind, values...) and returns Self& from it.
#pragma once
#include <cstdint>
#include "core/step.hpp"
#include "core/vec.hpp"

namespace sw {

template <class Self, class Num> struct GeometryEmitters {
  Self& point(const Vec2<Num>& p) { return self().geo(GeoKind::point2, p.x, p.y); }
  Self& point(const Vec3<Num>& p) { return self().geo(GeoKind::point3, p.x, p.y, p.z); }
  Self& segment(const Vec2<Num>& a, const Vec2<Num>& b) { return self().geo(GeoKind::segment2, a.x, a.y, b.x, b.y); }
  Self& segment(const Vec3<Num>& a, const Vec3<Num>& b) { return self().geo(GeoKind::segment3, a.x, a.y, a.z, b.x, b.y, b.z); }
  Self& arrow(const Vec2<Num>& from, const Vec2<Num>& to) { return self().geo(GeoKind::arrow, from.x, from.y, to.x, to.y); }
  Self& rect(const Vec2<Num>& lo, const Vec2<Num>& hi) { return self().geo(GeoKind::rect, lo.x, lo.y, hi.x, hi.y); }
  Self& circle(const Vec2<Num>& c, const Num& r) { return self().geo(GeoKind::circle, c.x, c.y, r); }
  Self& ray(const Vec3<Num>& o, const Vec3<Num>& d) { return self().geo(GeoKind::ray3, o.x, o.y, o.z, d.x, d.y, d.z); }
  Self& box(const Vec3<Num>& lo, const Vec3<Num>& hi) { return self().geo(GeoKind::box3, lo.x, lo.y, lo.z, hi.x, hi.y, hi.z); }
  Self& sphere(const Vec3<Num>& c, const Num& r) { return self().geo(GeoKind::sphere, c.x, c.y, c.z, r); }
  Self& triangle(const Vec3<Num>& a, const Vec3<Num>& b, const Vec3<Num>& c) {
    return self().geo(GeoKind::triangle3, a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z);
  }
  Self& plane(const Vec3<Num>& p, const Vec3<Num>& n) { return self().geo(GeoKind::plane, p.x, p.y, p.z, n.x, n.y, n.z); }
  // A tree node (quadtree, kd-tree, BVH): its id, its parent's id (-1 for the root) and its bounds.
  Self& node(std::int64_t id, std::int64_t parent, const Vec2<Num>& lo, const Vec2<Num>& hi) {
    return self().geo(GeoKind::node2, Num(id), Num(parent), lo.x, lo.y, hi.x, hi.y);
  }
  Self& node(std::int64_t id, std::int64_t parent, const Vec3<Num>& lo, const Vec3<Num>& hi) {
    return self().geo(GeoKind::node3, Num(id), Num(parent), lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
  }

 private:
  Self& self() { return static_cast<Self&>(*this); }
};

}  // namespace sw
