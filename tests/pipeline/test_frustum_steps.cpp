// frustum-cull step by step in exact mode against CGAL's planes through the view volume's corners
// (oracle/pipeline_oracle.cpp). The algorithm's plane values are at its own scale of each plane, so
// they are checked up to a positive factor: their signs, and ratios that do not depend on the scale.
// Inputs: the example, the corpus (tests/cases/pipeline/) and seeded cameras with rational frames.
#include <catch2/catch.hpp>
#include "pipeline/frustum_cull.hpp"
#include "pipeline_test_support.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::pipeline;

namespace {

// A box's eight corners, from its definition: an AABB's by picking lo or hi per axis, an OBB's as
// c +- h1 +- h2 +- h3.
std::array<V3, 8> box_corners(const pipe::Bounds<Rational>& b) {
  std::array<V3, 8> out;
  for (int k = 0; k < 8; ++k) {
    Vec3<Rational> p = b.c;
    if (b.kind == pipe::Bounds<Rational>::Kind::aabb) p = {(k & 1 ? b.hi : b.lo).x, (k & 2 ? b.hi : b.lo).y, (k & 4 ? b.hi : b.lo).z};
    else
      for (int a = 0; a < 3; ++a) p = p + Rational(k >> a & 1 ? 1 : -1) * b.h[a];
    out[k] = arr(p);
  }
  return out;
}

}  // namespace

TEST_CASE("pipeline: every exact step of frustum-cull against CGAL's planes", "[pipeline][steps]") {
  std::array<int, 3> outcomes{};
  for (const Json& j : inputs_of("frustum-cull")) {
    INFO(j.dump());
    const po::Camera cam = camera_of(j);
    const auto planes = po::planes(cam);
    std::vector<pipe::Bounds<Rational>> objs;
    std::vector<po::Cull> want;
    for (const Json& o : j["objects"]) {
      pipe::Bounds<Rational> b;
      using K = pipe::Bounds<Rational>::Kind;
      const Json& v = o.begin().value();
      if (o.contains("sphere")) b.kind = K::sphere, b.c = point_of(v["center"]), b.r = q_of(v["radius"]);
      else if (o.contains("aabb")) b.kind = K::aabb, b.lo = point_of(v["min"]), b.hi = point_of(v["max"]);
      else {
        b.kind = K::obb, b.c = point_of(v["center"]);
        for (int a = 0; a < 3; ++a) b.h[a] = point_of(v["axes"][a]);
      }
      objs.push_back(b);
    }
    Recorder<Rational> t;
    (void)pipe::frustum_cull<Rational>(cam, objs, t);
    std::size_t i = 0;
    po::Cull state = po::Cull::inside;
    for_each_step<pipe::FrustumCull>(t, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
      const auto& b = objs[std::min(i, objs.size() - 1)];
      // The oracle's plane k at a point, at the oracle's own scale.
      auto at = [&](int k, const Vec3<Rational>& p) { return dot(vec(planes[k].a), p) + planes[k].d; };
      if (line == "planes") {
        check_frustum_edges(g, cam);
      } else if (line == "object") {
        i = static_cast<std::size_t>(sv["i"].get_num().get_si());
        REQUIRE(i < objs.size());
        const auto& o = objs[i];
        using K = pipe::Bounds<Rational>::Kind;
        if (o.kind == K::sphere) {
          state = po::cull_sphere(cam, arr(o.c), o.r);
          CHECK(g.take(GeoKind::sphere).values == std::vector<Rational>{o.c.x, o.c.y, o.c.z, o.r});
        } else {
          const std::array<V3, 8> corners = box_corners(o);
          state = po::cull_corners(cam, corners);
          if (o.kind == K::aabb) CHECK(g.take(GeoKind::box3).values == std::vector<Rational>{o.lo.x, o.lo.y, o.lo.z, o.hi.x, o.hi.y, o.hi.z});
          else  // the 12 edges join corners of the box
            for (int e = 0; e < 12; ++e) {
              const GeoItem& seg = g.take(GeoKind::segment3);
              for (int end = 0; end < 2; ++end) {
                const V3 p{seg.values[3 * end], seg.values[3 * end + 1], seg.values[3 * end + 2]};
                CHECK(std::find(corners.begin(), corners.end(), p) != corners.end());
              }
            }
        }
        ++outcomes[static_cast<int>(state)];
      } else if (line == "sphere") {
        const int k = static_cast<int>(sv["k"].get_num().get_si());
        // s is the signed distance times |a| (the algorithm's scale): same sign as the oracle's, and
        // s^2 / (r^2 |a|^2) = distance^2 / r^2 whatever the scale.
        const Rational s = sv["s"], r2a2 = sv["r^2|a|^2"], want = at(k, b.c);
        const Rational a2 = dot(vec(planes[k].a), vec(planes[k].a));
        CHECK(sgn(s) == sgn(want));
        CHECK(s * s * b.r * b.r * a2 == want * want * r2a2);
        CHECK(sgn(r2a2) == sgn(b.r));
      } else if (line == "aabb" || line == "obb") {
        const int k = static_cast<int>(sv["k"].get_num().get_si());
        // s + rho and s - rho are the box's farthest and nearest corners along a (scaled).
        Rational hi_c, lo_c;
        bool first = true;
        for (const V3& corner : box_corners(b)) {
          const Rational v = at(k, vec(corner));
          if (first || v > hi_c) hi_c = v;
          if (first || v < lo_c) lo_c = v;
          first = false;
        }
        const Rational s = sv["s"], rho = sv["rho"];
        CHECK(sgn(s + rho) == sgn(hi_c));
        CHECK(sgn(s - rho) == sgn(lo_c));
        CHECK((s + rho) * lo_c == (s - rho) * hi_c);  // one positive scale for both corners
      } else if (line == "culled") {
        CHECK(sv["culled"] == 1);
        CHECK(state == po::Cull::outside);
      } else if (line == "kept") {
        CHECK(sv["culled"] == 0);
        CHECK(state != po::Cull::outside);
        CHECK(sv["straddles"] == int(state == po::Cull::straddles));
      } else {
        FAIL("unexpected line " << line);
      }
    });
  }
  for (int k = 0; k < 3; ++k) CHECK(outcomes[k] >= 3);
}
