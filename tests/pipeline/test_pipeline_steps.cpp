// The pipeline family step by step in exact mode: every variable and geometry item of every step,
// against the oracle (oracle/pipeline_oracle.cpp: similar triangles, the depth hyperbola, CGAL's
// orientations and planes through the view volume's corners) or a closed form written here. The
// culling tests' plane values are the algorithm's own scale of a plane, so they are checked up to a
// positive factor: their signs, and ratios that do not depend on the scale. Inputs: each example,
// the corpus (tests/cases/pipeline/) and seeded random cameras with rational frames.
#include <catch2/catch.hpp>
#include <algorithm>
#include <random>
#include "catalog.hpp"
#include "corpus.hpp"
#include "pipeline/backface_cull.hpp"
#include "pipeline/frustum_cull.hpp"
#include "pipeline/transform.hpp"
#include "pipeline_oracle.hpp"
#include "pipeline_test_support.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::pipeline;
namespace po = sw::pipeline_oracle;

namespace {

using V3 = std::array<Rational, 3>;
V3 arr(const Vec3<Rational>& v) { return {v.x, v.y, v.z}; }
Vec3<Rational> vec(const V3& a) { return {a[0], a[1], a[2]}; }

void check_vec(StepValues& sv, const std::string& name, const V3& want) {
  for (int k = 0; k < 3; ++k) CHECK(sv[name + "." + "xyz"[k]] == want[k]);
}

// The inputs of one algorithm: its example, its corpus cases and `random` seeded variations of
// the example's camera made by `vary`.
std::vector<Json> inputs_of(std::string_view id) {
  std::vector<Json> out{Json::parse(find_algorithm(id).example)};
  for (const Json& j : corpus("pipeline"))
    if (j.contains("camera") && j.contains(id == "transform" ? "points" : id == "backface-cull" ? "triangles" : "objects")) out.push_back(j);
  // Seeded cameras with rational frames: eyes at Pythagorean offsets from the target.
  std::mt19937_64 rng(std::hash<std::string_view>{}(id));
  const std::array<std::array<int, 3>, 6> eyes{{{0, 3, 4}, {3, 0, 4}, {4, 3, 0}, {0, -4, 3}, {0, 5, 12}, {-12, 0, 5}}};
  for (const auto& e : eyes) {
    Json j = out[0];
    const int scale = 1 + static_cast<int>(rng() % 3);
    j["camera"]["eye"] = {e[0] * scale, e[1] * scale, e[2] * scale};
    j["camera"]["target"] = {0, 0, 0};
    j["camera"]["up"] = {0, 1, 0};
    out.push_back(j);
  }
  return out;
}

pipe::Camera<Rational> camera_of(const Json& j) {
  // The runtime's parse (via the catalog) is the one under test elsewhere; here the camera is read
  // straight from the JSON, exactly.
  auto q = [](const Json& v) { return q_of(v); };
  auto v3 = [&](const Json& v) { return Vec3<Rational>{q(v[0]), q(v[1]), q(v[2])}; };
  pipe::Camera<Rational> c;
  c.look = {v3(j["camera"]["eye"]), v3(j["camera"]["target"]), v3(j["camera"]["up"])};
  const bool persp = j["projection"].contains("perspective");
  const Json& b = persp ? j["projection"]["perspective"] : j["projection"]["orthographic"];
  c.proj = {persp, q(b[0]), q(b[1]), q(b[2]), q(b[3]), q(b[4]), q(b[5])};
  const Json& v = j["viewport"];
  c.view = {q(v[0]), q(v[1]), q(v[2]), q(v[3]), Rational(0), Rational(1)};
  if (j.contains("depth_range")) c.view.dn = q(j["depth_range"][0]), c.view.df = q(j["depth_range"][1]);
  return c;
}


// A segment3 item whose two ends are corners of the oracle's view volume.
void check_frustum_edges(StepGeometry& g, const po::Camera& cam) {
  const auto corners = po::corners(cam);
  for (int e = 0; e < 12; ++e) {
    GeoItem& item = g.take(GeoKind::segment3);
    CHECK(item.label == (e == 0 ? "frustum" : ""));
    CHECK(item.life == "keep");
    for (int end = 0; end < 2; ++end) {
      const V3 p{item.values[3 * end], item.values[3 * end + 1], item.values[3 * end + 2]};
      CHECK(std::find(corners.begin(), corners.end(), p) != corners.end());
    }
  }
}

}  // namespace

TEST_CASE("pipeline: every exact step of transform against the oracle", "[pipeline][steps]") {
  int vertices = 0, behind = 0;
  for (const Json& j : inputs_of("transform")) {
    INFO(j.dump());
    const po::Camera cam = camera_of(j);
    const po::Frame fr = po::frame(cam);
    pipe::Mat4<Rational> M{};
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 4; ++k) M[i][k] = i == k ? 1 : 0;
    if (j.contains("model"))
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 4; ++k) M[i][k] = q_of(j["model"][i][k]);
    std::vector<Vec3<Rational>> pts;
    for (const Json& p : j["points"]) pts.push_back(point_of(p));
    Recorder<Rational> t;
    (void)pipe::transform<Rational>(M, cam, pts, t);
    std::optional<po::Vertex> v;
    for_each_step<pipe::TransformAlgo>(t, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
      if (line == "frame") {
        check_vec(sv, "f", fr.fwd), check_vec(sv, "s", fr.right), check_vec(sv, "u", fr.up);
        CHECK(g.take(GeoKind::point3).values == std::vector<Rational>{cam.look.eye.x, cam.look.eye.y, cam.look.eye.z});
        for (const V3& axis : {fr.fwd, fr.up}) {
          const GeoItem& s = g.take(GeoKind::segment3);
          for (int k = 0; k < 3; ++k) CHECK(s.values[3 + k] - s.values[k] == axis[k]);
        }
      } else if (line == "matrices") {
        check_frustum_edges(g, cam);
      } else if (line == "model") {
        const std::size_t i = static_cast<std::size_t>(sv["i"].get_num().get_si());
        REQUIRE(i < pts.size());
        v = po::transform(M, cam, arr(pts[i]));
        ++vertices;
        check_vec(sv, "m", v->world);
        CHECK(g.take(GeoKind::point3).values == std::vector<Rational>(v->world.begin(), v->world.end()));
      } else if (line == "eye") {
        check_vec(sv, "e", v->eye);
      } else if (line == "clip") {
        CHECK(sv["c.size"] == 4);
        for (int k = 0; k < 4; ++k) CHECK(sv["c[" + std::to_string(k) + "]"] == v->clip[k]);
      } else if (line == "inside") {
        CHECK(sv["inside"] == int(v->inside));
      } else if (line == "behind") {
        CHECK(!v->win);
        ++behind;
      } else if (line == "divide") {
        REQUIRE(v->ndc);
        check_vec(sv, "ndc", *v->ndc);
      } else if (line == "window") {
        REQUIRE(v->win);
        check_vec(sv, "win", *v->win);
        CHECK(sv["depth"] == (*v->win)[2]);
      } else {
        FAIL("unexpected line " << line);
      }
    });
  }
  CHECK(vertices >= 50);
  CHECK(behind >= 2);
}

TEST_CASE("pipeline: every exact step of backface-cull against orientations", "[pipeline][steps]") {
  int edge_on = 0, behind = 0, faces = 0;
  for (const Json& j : inputs_of("backface-cull")) {
    INFO(j.dump());
    const po::Camera cam = camera_of(j);
    std::vector<pipe::Triangle<Rational>> tris;
    for (const Json& tj : j["triangles"]) tris.push_back({point_of(tj[0]), point_of(tj[1]), point_of(tj[2])});
    const auto mode = !j.contains("cull") ? pipe::CullFace::back : j["cull"] == "front" ? pipe::CullFace::front
                      : j["cull"] == "back" ? pipe::CullFace::back : pipe::CullFace::front_and_back;
    const auto front_face = j.contains("front_face") && j["front_face"] == "cw" ? pipe::FrontFace::cw : pipe::FrontFace::ccw;
    Recorder<Rational> t;
    (void)pipe::backface_cull<Rational>(cam, tris, mode, front_face, t);
    std::size_t i = 0;
    po::Facing f;
    std::array<V3, 3> win;
    for_each_step<pipe::BackfaceCull>(t, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
      const auto& tri = tris[std::min(i, tris.size() - 1)];
      if (line == "camera") {
        check_vec(sv, "f", po::frame(cam).fwd);
        CHECK(g.take(GeoKind::point3).values == std::vector<Rational>{cam.look.eye.x, cam.look.eye.y, cam.look.eye.z});
      } else if (line == "normal") {
        i = static_cast<std::size_t>(sv["i"].get_num().get_si());
        REQUIRE(i < tris.size());
        const auto& tr = tris[i];
        f = po::facing(cam, {arr(tr.a), arr(tr.b), arr(tr.c)});
        ++faces;
        check_vec(sv, "N", arr(cross(Vec3<Rational>(tr.b - tr.a), Vec3<Rational>(tr.c - tr.a))));
        CHECK(g.take(GeoKind::triangle3).values.size() == 9);
      } else if (line == "toward") {
        // V.N by its definition: V from a to the eye (perspective), or against the view direction.
        const Vec3<Rational> n = cross(Vec3<Rational>(tri.b - tri.a), Vec3<Rational>(tri.c - tri.a));
        const Vec3<Rational> view = cam.proj.perspective ? Vec3<Rational>(cam.look.eye - tri.a) : Vec3<Rational>(Rational(-1) * vec(po::frame(cam).fwd));
        CHECK(sv["V.N"] == dot(view, n));
        CHECK(sv["toward"] == f.toward);
        edge_on += f.toward == 0;
      } else if (line == "behind") {
        CHECK(!f.winding);
        ++behind;
      } else if (line == "project") {
        REQUIRE(f.winding);
        for (int k = 0; k < 3; ++k) {
          pipe::Mat4<Rational> I{};
          for (int a = 0; a < 4; ++a) I[a][a] = 1;
          win[k] = *po::transform(I, cam, arr(k == 0 ? tri.a : k == 1 ? tri.b : tri.c)).win;
          const std::string name = k == 0 ? "a'" : k == 1 ? "b'" : "c'";
          CHECK(sv[name + ".x"] == win[k][0]);
          CHECK(sv[name + ".y"] == win[k][1]);
        }
      } else if (line == "winding") {
        const Rational area2 = (win[1][0] - win[0][0]) * (win[2][1] - win[0][1]) - (win[1][1] - win[0][1]) * (win[2][0] - win[0][0]);
        CHECK(sv["area2"] == area2);
        CHECK(sv["winding"] == *f.winding);
      } else if (line == "front") {
        CHECK(sv["front"] == int(front_face == pipe::FrontFace::ccw ? *f.winding > 0 : *f.winding < 0));
      } else if (line == "agree") {
        CHECK(sv["agree"] == 1);  // in front of the eye the two tests agree exactly
      } else if (line == "cull") {
        const int side = f.winding ? *f.winding : f.toward;
        const bool front = front_face == pipe::FrontFace::ccw ? side > 0 : side < 0;
        CHECK(sv["culled"] == int(mode == pipe::CullFace::front_and_back || (mode == pipe::CullFace::back) != front));
      } else {
        FAIL("unexpected line " << line);
      }
    });
  }
  CHECK(faces >= 20);
  CHECK(edge_on >= 3);
  CHECK(behind >= 1);
}

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
          std::array<V3, 8> corners;
          for (int k = 0; k < 8; ++k) {
            Vec3<Rational> p = o.kind == K::aabb ? Vec3<Rational>{(k & 1 ? o.hi : o.lo).x, (k & 2 ? o.hi : o.lo).y, (k & 4 ? o.hi : o.lo).z} : o.c;
            if (o.kind == K::obb)
              for (int a = 0; a < 3; ++a) p = p + Rational(k >> a & 1 ? 1 : -1) * o.h[a];
            corners[k] = arr(p);
          }
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
        for (int c = 0; c < 8; ++c) {
          Vec3<Rational> p = b.kind == pipe::Bounds<Rational>::Kind::aabb ? Vec3<Rational>{(c & 1 ? b.hi : b.lo).x, (c & 2 ? b.hi : b.lo).y, (c & 4 ? b.hi : b.lo).z} : b.c;
          if (b.kind == pipe::Bounds<Rational>::Kind::obb)
            for (int a = 0; a < 3; ++a) p = p + Rational(c >> a & 1 ? 1 : -1) * b.h[a];
          const Rational v = at(k, p);
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
