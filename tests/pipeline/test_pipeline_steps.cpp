// transform and backface-cull step by step in exact mode: every variable and geometry item of every
// step, against the oracle (oracle/pipeline_oracle.cpp: similar triangles, the depth hyperbola,
// CGAL's orientations) or a closed form written here. Inputs: each example, the corpus
// (tests/cases/pipeline/) and seeded cameras with rational frames. frustum-cull: test_frustum_steps.cpp.
#include <catch2/catch.hpp>
#include <algorithm>
#include <random>
#include "catalog.hpp"
#include "corpus.hpp"
#include "pipeline/backface_cull.hpp"
#include "pipeline/transform.hpp"
#include "pipeline_oracle.hpp"
#include "pipeline_test_support.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::pipeline;


TEST_CASE("pipeline: every exact step of transform against the oracle", "[pipeline][steps]") {
  int vertices = 0, behind = 0;
  for (const Json& j : inputs_of("transform")) {
    INFO(j.dump());
    const po::Camera cam = camera_of(j);
    const po::Frame fr = po::frame(cam);
    pipe::Mat4<Rational> M = pipe::identity<Rational>();
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
          win[k] = *po::transform(pipe::identity<Rational>(), cam, arr(k == 0 ? tri.a : k == 1 ? tri.b : tri.c)).win;
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
