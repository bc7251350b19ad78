// projective-shadow: exact and filtered against the oracle's closed form; the depth tie lost with
// GL_LESS and kept with GL_LEQUAL or an offset, in exact; float z-fighting; the stencil keeping the
// shadow on a finite receiver and darkening each pixel once; bad input; every exact step against a
// standalone eye pass and closed forms (the matrix, the stencil, the depth test).
#include <catch2/catch.hpp>
#include "refusals.hpp"
#include "catalog.hpp"
#include "corpus.hpp"
#include "run.hpp"
#include "shadows/projective_shadow_input.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::shadowspec;

namespace {

std::shared_ptr<const ProjectiveInput> projective_of(const Json& j) { return parse_projective_input(j).p; }

ProjectivePixels projective_checked(const ProjectiveInput& in) {
  const ProjectivePixels want = projective_oracle(in);
  ProjectivePixels exact;
  for (Numeric n : {Numeric::exact, Numeric::filtered}) {
    const ProjectivePixels got = projected(in, n);
    CHECK(got.shadowed == want.shadowed);
    CHECK(got.missing == want.missing);
    CHECK(got.spurious == want.spurious);
    if (n == Numeric::exact) exact = got;
  }
  return exact;
}

std::int64_t shadowed_facing(const ProjectiveInput& in) {
  std::int64_t n = 0;
  for (std::size_t k = 0; k < in.seen->points.size(); ++k) n += in.seen->points[k].object == in.receiver && in.seen->faces[k] && !in.seen->reaches[k];
  return n;
}

}  // namespace

TEST_CASE("projective-shadow: exact and filtered equal the closed form on the eye's rays", "[shadows][projective]") {
  std::int64_t cases = 0;
  const auto sets = projective_sets();
  for (const ProjectiveInputRef& in : sets[0].inputs) (void)projective_checked(*in.p), ++cases;
  for (const Json& j : testing::corpus("shadows", "projective-shadow")) {
    INFO(j.dump().substr(0, 200));
    (void)projective_checked(*projective_of(j)), ++cases;
  }
  CHECK(cases >= 15);
}

TEST_CASE("projective-shadow: the depth tie, lost by GL_LESS, kept by GL_LEQUAL or an offset, and float z-fights", "[shadows][projective]") {
  std::int64_t shadowed = 0, lost = 0, kept_missing = 0, kept_spurious = 0, offset_missing = 0, float_missing = 0, float_spurious = 0;
  for (const char* scene : {"scenes/spot-lit.json", "scenes/glass-spheres.json", "scenes/eye-in-shadow.json"}) {
    INFO(scene);
    const Json base{{"scene", scene}, {"size", {40, 30}}, {"stacks", 6}};
    Json less = base, lequal = base, offset = base;
    less["depth"] = "less", lequal["depth"] = "lequal", offset["depth"] = "less", offset["offset"] = {-1, -1};
    const auto a = projective_of(less), b = projective_of(lequal), c = projective_of(offset);
    const ProjectivePixels pa = projected(*a, Numeric::exact), pb = projected(*b, Numeric::exact), pc = projected(*c, Numeric::exact);
    const ProjectivePixels fb = projected(*b, Numeric::f32);
    shadowed += shadowed_facing(*a);
    lost += pa.missing, kept_missing += pb.missing, kept_spurious += pb.spurious + pc.spurious, offset_missing += pc.missing;
    float_missing += fb.missing, float_spurious += fb.spurious;
    CHECK(pa.missing == shadowed_facing(*a));  // every shadow fragment ties with the receiver: GL_LESS drops all
    CHECK(pa.ties > 0);
  }
  CHECK(shadowed > 300);
  CHECK(lost == shadowed);
  CHECK(kept_missing == 0);    // exact GL_LEQUAL: the shadow is exact visibility on the plane
  CHECK(offset_missing == 0);  // and so with GL_LESS and glPolygonOffset(-1, -1)
  CHECK(kept_spurious == 0);
  CHECK(float_missing > 0);  // float: the tie goes either way, z-fighting
  WARN("projective shadows, exact: GL_LESS loses " << lost << " of " << shadowed << " shadowed floor points; float GL_LEQUAL misses " << float_missing
                                                    << " and adds " << float_spurious);
}

TEST_CASE("projective-shadow: the stencil keeps the shadow on a finite receiver and darkens once", "[shadows][projective]") {
  // The Cornell box's floor is two triangles; object 0 receives, and without the stencil the
  // boxes' shadows spill over the other half and over the walls behind the plane.
  const Json base{{"scene", "scenes/cornell-box.json"}, {"size", {40, 40}}, {"stacks", 3}, {"receiver", 0}, {"depth", "lequal"}};
  Json off = base;
  off["stencil"] = false;
  const auto on = projective_of(base), no = projective_of(off);
  const ProjectivePixels p_on = projective_checked(*on), p_no = projective_checked(*no);
  CHECK(p_on.off_receiver == 0);
  CHECK(p_on.doubled == 0);
  CHECK(p_no.off_receiver > 0);
  CHECK(p_no.doubled > 0);
  CHECK(p_on.missing == 0);
  CHECK(p_on.spurious == 0);
}

TEST_CASE("projective-shadow: bad input is one line naming the problem", "[shadows][projective][input]") {
  const Algorithm& alg = find_algorithm("projective-shadow");
  for (const auto& [text, needle] : std::vector<std::pair<std::string, std::string>>{
           {R"({"scene":"scenes/spot-lit.json","size":[8,8],"receiver":1})", "input.receiver: object 1 is a sphere"},
           {R"({"scene":"scenes/spot-lit.json","size":[8,8],"receiver":9})", "input.receiver"},
           {R"({"scene":"scenes/spot-lit.json","size":[8,8],"depth":"greater"})", "input.depth"},
           {R"({"scene":"scenes/spot-lit.json","size":[8,8],"offset":[1]})", "input.offset"},
           {R"({"scene":"scenes/spot-lit.json","size":[8,8],"offset":[1,1e9]})", "input.offset"},
           {R"({"scene":"scenes/spot-lit.json","size":[8,8],"stencil":"yes"})", "input.stencil"},
           {R"({"scene":"scenes/spot-lit.json","size":[8,8],"method":"zfail"})", "method"},
           {R"({"scene":{"camera":{"eye":[0,2,6],"vpn":[0,0.25,1],"vup":[0,1,0],"d":1,"fov":40,"resolution":[8,8]},"materials":{"m":{}},
               "lights":[{"type":"point","position":[1,0,0]}],"objects":[{"type":"plane","point":[0,0,0],"normal":[0,1,0],"material":"m"}]}})",
            "the light lies in the receiver's plane"},
           {R"({"scene":{"camera":{"eye":[0,2,6],"vpn":[0,0.25,1],"vup":[0,1,0],"d":1,"fov":40,"resolution":[8,8]},"materials":{"m":{}},
               "lights":[{"type":"point","position":[1,3,0]}],"objects":[{"type":"sphere","center":[0,0,0],"radius":1,"material":"m"}]}})",
            "no plane or triangle"}}) {
    testing::expect_refused(alg, text, needle);
  }
}

TEST_CASE("projective-shadow: every exact step against a standalone eye pass and closed forms", "[shadows][projective][steps]") {
  using namespace sw::testing;
  std::vector<Json> inputs{Json::parse(R"({"scene":"scenes/spot-lit.json","size":[16,12],"stacks":3,"depth":"less","offset":[-1,-1]})"),
                           Json::parse(R"({"scene":"scenes/cornell-box.json","size":[12,12],"stacks":3,"receiver":0,"depth":"lequal","stencil":false})")};
  for (const Json& j : corpus("shadows", "projective-shadow")) inputs.push_back(j);
  std::int64_t cut_away = 0;
  for (const Json& text : inputs) {
    INFO(text.dump().substr(0, 200));
    const auto in = projective_of(text);
    const RasterScene& sc = *in->seen->scene;
    const auto tris = pipespec::triangles_in<Rational>(sc.tris);
    Recorder<Rational> t;
    const auto img = shadow::projective_shadow<Rational>(sc.camera, tris, in->receiver, in->plane, in->light, in->params, t);
    Recorder<Rational> eye_steps;
    const auto eye = pipe::scene_raster<Rational>(sc.camera, tris, eye_steps);
    const std::int64_t w = sc.width;
    const auto& P = in->plane;
    const auto& L = in->light;
    const Rational PL = P.x * L.x + P.y * L.y + P.z * L.z + P.w * L.w;
    // The plane's slope in the eye's window from a point on it and two directions along it.
    const Vec3<Rational> n{P.x, P.y, P.z}, Y = Rational(-P.w) / dot(n, n) * n;
    const Vec3<Rational> e1 = num::abs(n.x) < num::abs(n.y) ? cross(n, Vec3<Rational>{1, 0, 0}) : cross(n, Vec3<Rational>{0, 1, 0});
    const Rational slope = window_slope(pipe::raster_matrix(sc.camera), sc.camera, Y, e1, cross(n, e1));
    std::vector<std::uint8_t> stencil(eye.buffer.id.size(), 0);
    std::int64_t on = 0;
    for (std::size_t i = 0; i < stencil.size(); ++i)
      if (eye.buffer.id[i] >= 0 && eye.drawn[std::size_t(eye.buffer.id[i])][0] == in->receiver) stencil[i] = 1, ++on;
    std::size_t nested = 0;
    bool after = false, pass = false;
    std::int64_t fi = 0, fj = 0, fragments = 0, ties = 0, dark = 0;
    Rational d, D;
    for_each_step<shadow::ProjectiveShadow>(t, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
      if (line == "depth") {
        after = true;
        CHECK(sv["passed"] == eye.buffer.passed);
        CHECK(nested == eye_steps.size());
      } else if (line == "matrix") {
        CHECK(sv["PL"] == PL);
        CHECK(sv["S.size"] == 16);
        const std::array<Rational, 4> l{L.x, L.y, L.z, L.w}, p{P.x, P.y, P.z, P.w};
        for (int k = 0; k < 16; ++k) CHECK(sv["S[" + std::to_string(k) + "]"] == (k / 4 == k % 4 ? PL : Rational(0)) - l[std::size_t(k / 4)] * p[std::size_t(k % 4)]);
      } else if (line == "stencil") {
        CHECK(sv["receiver"] == in->receiver);
        CHECK(sv["pixels"] == on);
      } else if (line == "occluder") {
        const Rational object = sv["object"], prim = sv["prim"];
        CHECK(object != in->receiver);
        const Rational k = sv["corners"];
        CHECK((k == 0 || (k >= 3 && k <= 5)));  // a triangle cut by two planes
        // Wholly below the plane, or wholly beyond the light's height above it: nothing is kept.
        for (const auto& tri : sc.tris)
          if (tri.object == object && tri.prim == prim) {
            bool below = true, beyond = true;
            for (const auto& x : tri.x) {
              const Rational h = P.x * x.x + P.y * x.y + P.z * x.z + P.w * x.w;
              below = below && h < 0, beyond = beyond && PL * x.w - L.w * h < 0;
            }
            if (below || beyond) CHECK(k == 0);
            if (below || beyond) ++cut_away;
          }
      } else if (line == "project") {
        const Rational k = sv["corners"];
        CHECK((k >= 3 && k <= pipe::kMaxClipCorners));
        CHECK(Rational(std::int64_t(g.take(GeoKind::polygon).values.size())) == 2 * k);
      } else if (line == "offset") {
        // The shadow polygon lies in the receiver's plane: its window slope is the plane's, by closed form.
        CHECK(std::max(num::abs(sv["zx"]), num::abs(sv["zy"])) == slope);
        CHECK(sv["o"] == in->params.factor * slope + in->params.units / Rational(1 << 24));
      } else if (line == "fragment") {
        fi = sv["i"].get_num().get_si(), fj = sv["j"].get_num().get_si();
        CHECK(g.take(GeoKind::pixel).values == std::vector<Rational>{Rational(fi), Rational(fj)});
        d = sv["d"], D = sv["D"];
        CHECK(D == eye.buffer.depth[std::size_t(fj * w + fi)]);
        ++fragments, ties += d == D;
      } else if (line == "test") {
        const bool depth = in->params.lequal ? d <= D : d < D;
        CHECK(sv["depth"] == int(depth));
        CHECK(sv["stencil"] == stencil[std::size_t(fj * w + fi)]);
        pass = depth && (!in->params.stencil || stencil[std::size_t(fj * w + fi)] == 1);
        CHECK(sv["pass"] == int(pass));
      } else if (line == "darken") {
        CHECK(pass);
        auto& px = g.take(GeoKind::pixel);
        CHECK(px.values == std::vector<Rational>{Rational(fi), Rational(fj)});
        CHECK(px.value == Rational(1));
        dark += stencil[std::size_t(fj * w + fi)] != 2;
        stencil[std::size_t(fj * w + fi)] = 2;
      } else if (line == "done") {
        CHECK(sv["shadowed"] == dark);
        CHECK(sv["ties"] == ties);
        CHECK(sv["fragments"] == fragments);
      } else {
        FAIL("unexpected line " << line);
      }
    }, [&](std::size_t s) {
      if (!after) {
        REQUIRE(nested < eye_steps.size());
        CHECK(values_of(t, s).v == values_of(eye_steps, nested).v);
        ++nested;
      } else {
        CHECK(t.scope_id(t.at(s).scope) == pipe::ClipVolume::id);
      }
    });
    CHECK(img.fragments == fragments);
  }
  CHECK(cut_away > 0);  // the triangles below the floor and above the light
}

#include <filesystem>
#include "cli_harness.hpp"
#include "data_root.hpp"

TEST_CASE("scene raster --shadows projective: a line per light, and a bad receiver leaves no file", "[shadows][projective][cli]") {
  const auto dir = testing::scratch("scene-raster-projective");
  const std::string png = (dir / "r.png").string();
  const std::string scene = testing::sh_quote((data_root() / "scenes" / "spot-lit.json").string());
  const testing::Ran r = testing::run_stepwise("scene raster " + scene + " --size 40x30 --stacks 4 --shadows projective --out " + testing::sh_quote(png));
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out.find("light 0: projective onto object 0 (GL_LESS, glPolygonOffset(-1, -1), stencil)") != std::string::npos);
  CHECK(r.out.find("missing 0, spurious 0") != std::string::npos);
  CHECK(std::filesystem::exists(png));
  for (const std::string bad : {" --shadows projective --receiver 1", " --shadows projective --receiver 99", " --shadows map --receiver 0"}) {
    const testing::Ran b = testing::expect_cli_refused("scene raster " + scene + " --size 16x16" + bad + " --out " + testing::sh_quote(png), png);
    CHECK(b.err.find("--receiver") != std::string::npos);
  }
}
