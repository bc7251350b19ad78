// scene-raster step by step in exact mode: the camera's frame and matrix against closed forms, each
// triangle's clip coordinates, every step of its nested clip (each distance, kept and cut corner from
// the corners before it), the kept polygon against the brute-force intersection of half-planes, its
// window corners and fan, and the nested z-buffer against a standalone z-buffer of those fans.
#include <catch2/catch.hpp>
#include <cmath>
#include "catalog.hpp"
#include "pipeline/raster_scene.hpp"
#include "pipeline_test_support.hpp"
#include "raster_test_support.hpp"
#include "tracer/history.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::pipespec;

namespace {

using raster::V4, raster::same, raster::plane_distance, raster::brute_clip;

V4 times(const std::array<Rational, 16>& m, const V4& x) {
  std::array<Rational, 4> o;
  for (int r = 0; r < 4; ++r) o[r] = m[4 * r] * x.x + m[4 * r + 1] * x.y + m[4 * r + 2] * x.z + m[4 * r + 3] * x.w;
  return {o[0], o[1], o[2], o[3]};
}
V4 list4(StepValues& sv, const std::string& name) {
  CHECK(sv[name + ".size"] == 4);
  return {sv[name + "[0]"], sv[name + "[1]"], sv[name + "[2]"], sv[name + "[3]"]};
}

std::vector<Json> step_inputs() {
  return {Json::parse(find_algorithm("scene-raster").example), Json::parse(R"({"scene":"scenes/cornell-box.json","size":[16,16]})"),
          Json::parse(R"({"scene":{"camera":{"eye":[0,0,6],"vpn":["1/8",0,1],"vup":[0,1,0],"d":1,"window":["-1/2","1/2","-3/8","3/8"],"resolution":[16,12]},
             "materials":{"m":{}},"lights":[],"objects":[
             {"type":"plane","point":[0,-1,0],"normal":[0,1,"1/8"],"material":"m"},
             {"type":"triangle","vertices":[[-9,-9,9],[-2,-9,-9],["-5/2",9,-9]],"material":"m"},
             {"type":"triangle","vertices":[[0,0,7],[2,0,-3],[-1,0,-5]],"material":"m"},
             {"type":"triangle","vertices":[[-1,-1,9],[1,-1,9],[0,1,9]],"material":"m"},
             {"type":"box","min":[-1,-1,-2],"max":[1,"1/2",-1],"material":"m"},
             {"type":"sphere","center":[2,1,-4],"radius":1,"material":"m"}]},"size":[16,12],"stacks":3})")};
}

}  // namespace

TEST_CASE("scene-raster: every exact step against closed forms and the brute-force clip", "[pipeline][raster][steps]") {
  int triangles = 0, kept = 0, all_cuts = 0, all_culled = 0, nested_clip = 0, nested_z = 0;
  for (const Json& j : step_inputs()) {
    int cuts = 0, culled = 0;
    INFO(j.dump().substr(0, 200));
    std::string name;
    const auto s = raster_scene(tracer::scene_input(j["scene"], &name),
                                RasterOptions{j["size"][0].get<std::int64_t>(), j["size"][1].get<std::int64_t>(), j.value("stacks", kDefaultStacks)});
    const pipe::RasterCamera<Rational>& cam = s->camera;
    Recorder<Rational> t;
    (void)pipe::scene_raster<Rational>(camera_in<Rational>(cam), triangles_in<Rational>(s->tris), t);
    std::array<Rational, 16> M;
    std::size_t tri = 0;
    std::array<V4, 3> corners;
    std::vector<V4> poly, next;  // the nested clip's polygon before and after the current plane
    int plane = -1;
    std::vector<pipe::DepthTriangle<Rational>> window;
    Recorder<Rational> standalone;
    std::int64_t passed = -1;
    std::size_t z_step = 0;
    V4 edge_p, edge_q;  // the clip's current edge
    Rational edge_dp, edge_dq;
    for_each_step<pipe::SceneRaster>(t, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
      if (line == "view") {
        // The tracer's frame as double computes it, taken exactly.
        const tracer::Camera& c = s->scene->camera;
        const Vec3<double> vpn{c.vpn.d[0], c.vpn.d[1], c.vpn.d[2]}, vup{c.vup.d[0], c.vup.d[1], c.vup.d[2]};
        const Vec3<double> n = (1.0 / std::sqrt(dot(vpn, vpn))) * vpn;
        const Vec3<double> uu = cross(vup, n), u = (1.0 / std::sqrt(dot(uu, uu))) * uu, v = cross(n, u);
        auto q3 = [](const Vec3<double>& a) { return pipeline::V3{num::to_rational(a.x), num::to_rational(a.y), num::to_rational(a.z)}; };
        pipeline::check_vec(sv, "u", q3(u)), pipeline::check_vec(sv, "v", q3(v)), pipeline::check_vec(sv, "n", q3(n));
        pipeline::check_vec(sv, "eye", {num::to_rational(c.eye.d[0]), num::to_rational(c.eye.d[1]), num::to_rational(c.eye.d[2])});
      } else if (line == "project") {
        const Rational near = sv["near"];
        CHECK(near == cam.near);
        CHECK(sv["M.size"] == 16);
        for (int k = 0; k < 16; ++k) M[k] = sv["M[" + std::to_string(k) + "]"];
        // Four independent points pin M: the eye, and the eye plus the tracer's ray through three
        // pixel corners of the image, which land at their pixel's normalized coordinates.
        CHECK(same(times(M, {cam.eye.x, cam.eye.y, cam.eye.z, Rational(1)}), {0, 0, -2 * near, 0}));
        for (const auto& [i, jt] : {std::pair<std::int64_t, std::int64_t>{0, 0}, {cam.width - 1, 0}, {0, cam.height - 1}}) {
          const Rational wu = cam.window[0] + (Rational(i) + Rational(1, 2)) * (cam.window[1] - cam.window[0]) / cam.width;
          const Rational wv = cam.window[3] - (Rational(jt) + Rational(1, 2)) * (cam.window[3] - cam.window[2]) / cam.height;
          const Vec3<Rational> p = cam.eye + Vec3<Rational>(Rational(-cam.dist) * cam.n) + Vec3<Rational>(wu * cam.u) + Vec3<Rational>(wv * cam.v);
          const Rational sx = 2 * (Rational(i) + Rational(1, 2)) / cam.width - 1, sy = 1 - 2 * (Rational(jt) + Rational(1, 2)) / cam.height;
          CHECK(same(times(M, {p.x, p.y, p.z, Rational(1)}), {sx * cam.dist, sy * cam.dist, cam.dist - 2 * near, cam.dist}));
        }
        // The near plane is half the least eye depth of what the view pyramid holds (the sides'
        // brute-force clip of every triangle; a polygon through the eye is seen edge-on).
        std::optional<Rational> least;
        for (const auto& tr : s->tris) {
          std::array<V4, 3> c;
          for (int k = 0; k < 3; ++k) c[k] = times(M, tr.x[k]);
          const std::vector<V4> K = brute_clip(c, 1);
          if (std::any_of(K.begin(), K.end(), [](const V4& v) { return v.w == 0; })) continue;
          for (const V4& v : K)
            if (v.w != v.z) {  // a finite point: world w = (w - z)/(2 near), eye depth w / world w
              const Rational e = 2 * near * v.w / (v.w - v.z);
              if (!least || e < *least) least = e;
            }
        }
        CHECK(near == (least ? Rational(*least / 2) : cam.dist));
      } else if (line == "corners") {
        REQUIRE(tri < s->tris.size());
        const auto& tr = s->tris[tri++];
        CHECK(sv["object"] == tr.object);
        CHECK(sv["prim"] == tr.prim);
        for (int k = 0; k < 3; ++k) {
          corners[k] = times(M, tr.x[k]);
          CHECK(same(list4(sv, "c" + std::to_string(k)), corners[k]));
        }
        poly.assign(corners.begin(), corners.end()), next.clear(), plane = -1;
        ++triangles;
      } else if (line == "clip") {
        const std::vector<V4> want = brute_clip(corners, 0);
        CHECK(sv["corners"] == std::int64_t(want.size()));
        const bool cut = !(want.size() == 3 && std::all_of(corners.begin(), corners.end(), [&](const V4& c) {
          return std::any_of(want.begin(), want.end(), [&](const V4& w) { return same(w, c); });
        }));
        CHECK(sv["cut"] == int(cut && !want.empty()));
        if (want.empty()) ++culled;
        for (const V4& v : poly) CHECK(std::any_of(want.begin(), want.end(), [&](const V4& w) { return same(w, v); }));
        if (!want.empty()) CHECK(poly.size() == want.size());
        kept += !want.empty(), cuts += cut && !want.empty();
      } else if (line == "divide") {
        CHECK(sv["corners"] == std::int64_t(poly.size()));
        const GeoItem& item = g.take(GeoKind::polygon);
        CHECK(item.label == "K");
        CHECK(item.life == "replace");
        REQUIRE(item.values.size() == 2 * poly.size());
        std::vector<Vec3<Rational>> w;
        for (std::size_t k = 0; k < poly.size(); ++k) {
          const V4& c = poly[k];
          const Vec3<Rational> x{Rational(-1, 2) + (c.x / c.w + 1) * cam.width / 2, Rational(-1, 2) + (c.y / c.w + 1) * cam.height / 2, (c.z / c.w + 1) / 2};
          CHECK(item.values[2 * k] == x.x);
          CHECK(item.values[2 * k + 1] == x.y);
          w.push_back(x);
        }
        for (std::size_t k = 1; k + 1 < w.size(); ++k) window.push_back({{w[0], w[k], w[k + 1]}, std::int64_t(window.size()), Rational(0), Rational(0)});
      } else if (line == "fan") {
        CHECK(sv["triangles"] == std::int64_t(poly.size()) - 2);
        CHECK(sv["drawn"] == std::int64_t(window.size()));
      } else if (line == "draw") {
        CHECK(tri == s->tris.size());
        CHECK(sv["triangles"] == std::int64_t(window.size()));
        passed = pipe::z_buffer<Rational>(cam.width, cam.height, window, 0, pipe::DepthFunc::less, Rational(1), standalone).passed;
      } else if (line == "done") {
        CHECK(z_step == standalone.size());
        CHECK(sv["culled"] == culled);
        CHECK(sv["cut"] == cuts);
        CHECK(sv["passed"] == passed);
      } else {
        FAIL("unexpected line " << line);
      }
    }, [&](std::size_t st) {
      if (t.scope_id(t.at(st).scope) == pipe::ZBuffer::id) {
        // The nested z-buffer repeats a standalone z-buffer of the fans, value for value.
        REQUIRE(z_step < standalone.size());
        CHECK(values_of(t, st).v == values_of(standalone, z_step).v);
        CHECK(t.at(st).line == standalone.at(z_step).line);
        ++z_step, ++nested_z;
        return;
      }
      REQUIRE(t.scope_id(t.at(st).scope) == pipe::ClipVolume::id);
      ++nested_clip;
      const std::string_view line = pipe::ClipVolume::lines[t.at(st).line - 1].name;
      check_step(t, st, [&](StepValues& sv, StepGeometry&) {
        if (line == "plane") {
          if (plane >= 0) poly = next;
          plane = static_cast<int>(sv["p"].get_num().get_si());
          next.clear();
        } else if (line == "edge") {
          const std::size_t e = static_cast<std::size_t>(sv["e"].get_num().get_si());
          REQUIRE(e < poly.size());
          edge_p = poly[e], edge_q = poly[(e + 1) % poly.size()];
          const Rational dp = plane_distance(plane, edge_p), dq = plane_distance(plane, edge_q);
          edge_dp = dp, edge_dq = dq;
          CHECK(sv["dP"] == dp);
          CHECK(sv["dQ"] == dq);
          CHECK(sv["keep"] == int(dp >= 0));
          CHECK(sv["cut"] == int((dp < 0 && dq > 0) || (dp > 0 && dq < 0)));
        } else if (line == "keep") {
          const V4 c = list4(sv, "c");
          CHECK(plane_distance(plane, c) >= 0);
          CHECK(std::any_of(poly.begin(), poly.end(), [&](const V4& v) { return same(v, c); }));
          next.push_back(c);
        } else if (line == "cut") {
          const V4 c = list4(sv, "c");
          const Rational s_ = sv["s"];
          CHECK(s_ == edge_dp / (edge_dp - edge_dq));
          CHECK(same(c, {edge_p.x + s_ * (edge_q.x - edge_p.x), edge_p.y + s_ * (edge_q.y - edge_p.y), edge_p.z + s_ * (edge_q.z - edge_p.z),
                         edge_p.w + s_ * (edge_q.w - edge_p.w)}));
          CHECK(plane_distance(plane, c) == 0);
          next.push_back(c);
        } else if (line == "empty") {
          CHECK(sv["corners"] == std::int64_t(next.size()));
          CHECK(next.size() < 3);
          poly.clear(), plane = -1;
        } else if (line == "done") {
          poly = next, plane = -1;
          CHECK(sv["corners"] == std::int64_t(poly.size()));
        } else {
          FAIL("unexpected clip line " << line);
        }
      });
    });
    CHECK(z_step == standalone.size());
    all_cuts += cuts, all_culled += culled;
  }
  CHECK(triangles > 300);
  CHECK(kept > 200);
  CHECK(all_cuts >= 2);
  CHECK(all_culled >= 1);
  CHECK(nested_clip > 1000);
  CHECK(nested_z > 1000);
}
