// shadow-map step by step in exact mode: each view's pass against a standalone scene-raster from the
// light (its nested steps value for value), and every lookup against closed forms written here: the
// cube face, the point's window position and depth from the view's frame by Cramer's rule, the
// texel, the slope, the comparison and PCF's taps.
#include <catch2/catch.hpp>
#include "corpus.hpp"
#include "shadows/shadow_map_input.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::shadowspec;

namespace {

using V3 = Vec3<Rational>;

// Coordinates of x in the basis (u, v, n), by Cramer's rule.
V3 in_frame(const pipe::RasterCamera<Rational>& c, const V3& x) {
  auto det = [](const V3& a, const V3& b, const V3& d) { return dot(a, cross(b, d)); };
  const Rational D = det(c.u, c.v, c.n);
  return {det(x, c.v, c.n) / D, det(c.u, x, c.n) / D, det(c.u, c.v, x) / D};
}

// Where P lands in view c: window x, y and depth, from its eye-space coordinates.
std::array<Rational, 3> landing(const pipe::RasterCamera<Rational>& c, const V3& P) {
  const V3 e = in_frame(c, V3(P - c.eye));
  const Rational depth = -e.z;  // along the view direction, -n
  const Rational wu = c.orthographic ? e.x : e.x * c.dist / depth, wv = c.orthographic ? e.y : e.y * c.dist / depth;
  const Rational x = Rational(-1, 2) + (wu - c.window[0]) / (c.window[1] - c.window[0]) * c.width;
  const Rational y = Rational(-1, 2) + (wv - c.window[2]) / (c.window[3] - c.window[2]) * c.height;
  const Rational d = c.orthographic ? (depth - c.near) / (c.far - c.near) : 1 - c.near / depth;
  return {x, y, d};
}

// The slope of the plane through P along e1 and e2 on view c's window: three landings.
Rational slope_at(const pipe::RasterCamera<Rational>& c, const V3& P, const V3& e1, const V3& e2) {
  const Rational eps(1, 1 << 20);
  const auto a = landing(c, P), b = landing(c, V3(P + V3(eps * e1))), d = landing(c, V3(P + V3(eps * e2)));
  const Rational area = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
  if (area == 0) return 0;
  const Rational zx = ((b[2] - a[2]) * (d[1] - a[1]) - (d[2] - a[2]) * (b[1] - a[1])) / area;
  const Rational zy = ((d[2] - a[2]) * (b[0] - a[0]) - (b[2] - a[2]) * (d[0] - a[0])) / area;
  return std::max(num::abs(zx), num::abs(zy));
}

int face_of(const V3& d) {  // largest axis, ties x then y; +x, -x, +y, -y, +z, -z
  const Rational ax = num::abs(d.x), ay = num::abs(d.y), az = num::abs(d.z);
  if (ax >= ay && ax >= az) return d.x < 0 ? 1 : 0;
  if (ay >= az) return d.y < 0 ? 3 : 2;
  return d.z < 0 ? 5 : 4;
}

}  // namespace

TEST_CASE("shadow-map: every exact step against a standalone pass and closed forms", "[shadows][map][steps]") {
  std::vector<Json> inputs{Json::parse(R"({"scene":"scenes/spot-lit.json","size":[20,15],"stacks":3,"light":0,"map":{"size":24,"slope":2,"bias":"1/4096","pcf":3}})")};
  for (const Json& j : corpus("shadows", "shadow-map")) inputs.push_back(j);
  std::size_t lookups = 0, offmap = 0, cube = 0, ortho = 0, shadowed = 0;
  for (const Json& j : inputs) {
    INFO(j.dump().substr(0, 240));
    const auto in = parse_map_input(j).p;
    const MapOptions& o = in->options;
    const auto tris = pipespec::triangles_in<Rational>(in->scene->tris);
    std::vector<pipe::RasterCamera<Rational>> views = in->views.views;
    const auto points = map_points<Rational>(*in);
    Recorder<Rational> t;
    (void)shadow::shadow_map<Rational>(views, in->views.cube, in->views.position, tris, points, map_params<Rational>(o), t);
    cube += in->views.cube, ortho += views[0].orthographic;
    // The standalone passes, and a cursor into each one's steps for the nested ones.
    std::vector<Recorder<Rational>> pass(views.size());
    std::vector<pipe::DepthBuffer<Rational>> map;
    for (std::size_t v = 0; v < views.size(); ++v) map.push_back(pipe::scene_raster<Rational>(views[v], tris, pass[v], {Rational(0), Rational(0), o.bits}).buffer);
    const Rational scale = o.bits ? Rational((mpz_class(1) << o.bits) - 1) : Rational(1);
    std::size_t v_pass = 0, nested = 0, k = 0, lit = 0;
    int view = 0;
    std::array<Rational, 3> at{};
    std::int64_t ti = 0, tj = 0;
    Rational s_, ref;
    for_each_step<shadow::ShadowMap>(t, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
      if (line == "pass") {
        v_pass = static_cast<std::size_t>(sv["view"].get_num().get_si()), nested = 0;
        CHECK(sv["near"] == views[v_pass].near);
      } else if (line == "draw") {
        CHECK(sv["view"] == std::int64_t(v_pass));
        CHECK(sv["passed"] == map[v_pass].passed);
        CHECK(nested == pass[v_pass].size());
      } else if (line == "point") {
        k = static_cast<std::size_t>(sv["k"].get_num().get_si());
        REQUIRE(k < points.size());
        const V3& P = points[k].p;
        view = in->views.cube ? face_of(V3(P - in->views.position)) : 0;
        CHECK(sv["view"] == view);
        CHECK(g.take(GeoKind::point3).values == std::vector<Rational>{P.x, P.y, P.z});
        ++lookups;
      } else if (line == "project") {
        at = landing(views[std::size_t(view)], points[k].p);
        CHECK(sv["x"] == at[0]);
        CHECK(sv["y"] == at[1]);
        CHECK(sv["d"] == at[2]);
      } else if (line == "outside") {
        const auto& c = views[std::size_t(view)];
        ti = num::floor_int(Rational(at[0] + Rational(1, 2))), tj = num::floor_int(Rational(at[1] + Rational(1, 2)));
        CHECK((ti < 0 || tj < 0 || ti >= c.width || tj >= c.height));
        CHECK(sv["lit"] == 1);
        ++offmap, ++lit;
      } else if (line == "texel") {
        ti = num::floor_int(Rational(at[0] + Rational(1, 2))), tj = num::floor_int(Rational(at[1] + Rational(1, 2)));
        CHECK(sv["i"] == ti);
        CHECK(sv["j"] == tj);
        const auto& c = views[std::size_t(view)];
        CHECK(sv["D"] == map[std::size_t(view)].depth[std::size_t(tj * c.width + ti)] / scale);
        CHECK(g.take(GeoKind::pixel).values == std::vector<Rational>{Rational(ti), Rational(tj)});
      } else if (line == "slope") {
        s_ = o.slope == 0 ? Rational(0) : slope_at(views[std::size_t(view)], points[k].p, points[k].e1, points[k].e2);
        CHECK(sv["s"] == s_);
      } else if (line == "compare") {
        const auto& c = views[std::size_t(view)];
        const Rational D = map[std::size_t(view)].depth[std::size_t(tj * c.width + ti)] / scale;
        ref = at[2] - o.bias - o.slope * s_;
        CHECK(sv["ref"] == ref);
        CHECK(sv["D"] == D);
        CHECK(sv["lit"] == int(ref <= D));
        lit += ref <= D, shadowed += !(ref <= D);
      } else if (line == "pcf") {
        const auto& c = views[std::size_t(view)];
        std::int64_t taps = 0, passing = 0;
        for (std::int64_t b = tj - o.pcf / 2; b <= tj + o.pcf / 2; ++b)
          for (std::int64_t a = ti - o.pcf / 2; a <= ti + o.pcf / 2; ++a)
            if (a >= 0 && b >= 0 && a < c.width && b < c.height) ++taps, passing += ref <= map[std::size_t(view)].depth[std::size_t(b * c.width + a)] / scale;
        CHECK(sv["taps"] == taps);
        CHECK(sv["pass"] == passing);
        CHECK(sv["fraction"] == Rational(passing) / Rational(taps));
      } else if (line == "done") {
        CHECK(sv["points"] == std::int64_t(points.size()));
        CHECK(sv["lit"] == std::int64_t(lit));
      } else {
        FAIL("unexpected line " << line);
      }
    }, [&](std::size_t s) {
      // A pass's nested steps repeat the standalone scene-raster's, value for value.
      REQUIRE(nested < pass[v_pass].size());
      CHECK(values_of(t, s).v == values_of(pass[v_pass], nested).v);
      CHECK(t.at(s).line == pass[v_pass].at(nested).line);
      const Recorder<Rational>& alone = pass[v_pass];
      const std::uint8_t scope = alone.at(nested).scope;
      CHECK(t.scope_id(t.at(s).scope) == (scope == 0 ? pipe::SceneRaster::id : alone.scope_id(scope)));
      ++nested;
    });
  }
  CHECK(lookups > 1000);
  CHECK(offmap > 20);
  CHECK(shadowed > 50);
  CHECK(cube > 0);
  CHECK(ortho > 0);
}
