// blend and fog step by step in exact (and, for fog's exponentials, reference) mode against closed
// forms: each fragment's depth from the fill oracle's interpolation, each blended colour from the
// over operator applied to the colour the trace itself left there, the painter's order from the
// centroids, fog's factor from GL's formulas (the oracle's, e^x to 400 bits); and the final pictures against the
// brute-force oracle. Plus the order dependence the lesson rests on.
#include <catch2/catch.hpp>
#include <map>
#include <numeric>
#include "catalog.hpp"
#include "corpus.hpp"
#include "fill_oracle.hpp"
#include "pipeline/blend.hpp"
#include "pipeline/fog.hpp"
#include "pipeline_oracle.hpp"
#include "pipeline_test_support.hpp"
#include "run.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::pipeline;
namespace po = sw::pipeline_oracle;

namespace {

std::vector<Json> inputs_with(const char* key, std::string_view id) {
  std::vector<Json> out{Json::parse(find_algorithm(id).example)};
  for (const Json& j : corpus("pipeline"))
    if (j.contains(key)) out.push_back(j);
  return out;
}

bool close_to(const Rational& got, const Rational& want) {
  return abs(Rational(got - want)) <= Rational(1, mpz_class(1) << 200) * (1 + abs(want));
}

}  // namespace

TEST_CASE("blend: every exact step against the over operator, the pictures against the oracle", "[pipeline][blend][steps]") {
  int blended = 0, rejected = 0;
  for (const Json& j : inputs_with("background", "blend")) {
    INFO(j.dump());
    const std::int64_t w = j["size"][0], h = j["size"][1];
    std::vector<pipe::BlendTriangle<Rational>> tris;
    std::vector<po::BlendTriangle> otris;
    for (const Json& t : j["triangles"]) {
      pipe::BlendTriangle<Rational> b;
      po::BlendTriangle o;
      for (int k = 0; k < 3; ++k) b.v[k] = point_of(t["v"][k]), o.v[k] = {b.v[k].x, b.v[k].y, b.v[k].z};
      b.rgb = point_of(t["rgb"]), b.alpha = q_of(t["alpha"]);
      o.rgb = {b.rgb.x, b.rgb.y, b.rgb.z}, o.alpha = b.alpha;
      tris.push_back(b), otris.push_back(o);
    }
    const Vec3<Rational> bg = j.contains("background") ? point_of(j["background"]) : Vec3<Rational>{};
    const bool depth_write = j.value("depth_write", true);
    Recorder<Rational> rec;
    const auto got = pipe::blend<Rational>(w, h, tris, bg, depth_write, rec);
    // The painter's order from the centroids, and both pictures, against the oracle.
    std::vector<std::size_t> given(tris.size());
    std::iota(given.begin(), given.end(), std::size_t(0));
    std::vector<std::size_t> painter = given;
    std::stable_sort(painter.begin(), painter.end(), [&](std::size_t a, std::size_t b) {
      return tris[b].v[0].z + tris[b].v[1].z + tris[b].v[2].z < tris[a].v[0].z + tris[a].v[1].z + tris[a].v[2].z;
    });
    CHECK(got.painter == painter);
    const auto want_given = po::blend(w, h, otris, given, {bg.x, bg.y, bg.z}, depth_write);
    const auto want_sorted = po::blend(w, h, otris, painter, {bg.x, bg.y, bg.z}, depth_write);
    for (std::size_t k = 0; k < want_given.size(); ++k) {
      CHECK(got.given.colour[k] == Vec3<Rational>{want_given[k][0], want_given[k][1], want_given[k][2]});
      CHECK(got.sorted.colour[k] == Vec3<Rational>{want_sorted[k][0], want_sorted[k][1], want_sorted[k][2]});
    }
    // The steps, with the colour and depth the trace itself left at each pixel.
    std::map<std::pair<std::int64_t, std::int64_t>, Vec3<Rational>> colour;
    std::map<std::pair<std::int64_t, std::int64_t>, Rational> depth;
    std::size_t t = 0;
    std::pair<std::int64_t, std::int64_t> at;
    Rational z;
    for_each_step<pipe::Blend>(rec, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
      if (line == "pass") {
        CHECK((sv["order"] == 0 || sv["order"] == 1));
        colour.clear(), depth.clear();
      } else if (line == "sort") {
        CHECK(sv["painter.size"] == Rational(std::int64_t(painter.size())));
        for (std::size_t k = 0; k < painter.size(); ++k) CHECK(sv["painter[" + std::to_string(k) + "]"] == Rational(std::int64_t(painter[k])));
      } else if (line == "triangle") {
        t = static_cast<std::size_t>(sv["t"].get_num().get_si());
        REQUIRE(t < tris.size());
        CHECK(sv["alpha"] == tris[t].alpha);
        CHECK((Vec3<Rational>{sv["C_t.r"], sv["C_t.g"], sv["C_t.b"]} == tris[t].rgb));
      } else if (line == "test") {
        at = {sv["i"].get_num().get_si(), sv["j"].get_num().get_si()};
        const std::array<Vec2<Rational>, 3> xy{Vec2<Rational>{tris[t].v[0].x, tris[t].v[0].y}, {tris[t].v[1].x, tris[t].v[1].y}, {tris[t].v[2].x, tris[t].v[2].y}};
        z = oracle::linear_at(xy, {tris[t].v[0].z, tris[t].v[1].z, tris[t].v[2].z}, Pixel{at.first, at.second});
        CHECK(sv["z"] == z);
        const Rational stored = depth.count(at) ? depth[at] : Rational(1);
        CHECK(sv["depth"] == stored);
        CHECK(sv["pass"] == int(z < stored));
        rejected += !(z < stored);
      } else if (line == "blend") {
        const Vec3<Rational> before = colour.count(at) ? colour[at] : bg;
        const Vec3<Rational> want = Vec3<Rational>(tris[t].alpha * tris[t].rgb) + Vec3<Rational>(Rational(1 - tris[t].alpha) * before);
        CHECK((Vec3<Rational>{sv["colour.r"], sv["colour.g"], sv["colour.b"]} == want));
        colour[at] = want;
        CHECK(g.take(GeoKind::pixel).values == std::vector<Rational>{Rational(at.first), Rational(at.second)});
        ++blended;
      } else if (line == "write") {
        CHECK(depth_write);
        CHECK(sv["depth"] == z);
        depth[at] = z;
      } else if (line == "compare") {
        std::int64_t differ = 0;
        for (std::size_t k = 0; k < want_given.size(); ++k) differ += want_given[k] != want_sorted[k];
        CHECK(sv["differ"] == Rational(differ));
      } else {
        FAIL("unexpected line " << line);
      }
    });
  }
  CHECK(blended >= 100);
  CHECK(rejected >= 10);
}

TEST_CASE("blend: the over operator depends on the order, and painter's order repairs depth writes", "[pipeline][blend]") {
  const Algorithm& alg = find_algorithm("blend");
  Json j = Json::parse(alg.example);
  // The example lists the near blue triangle first: with depth writes, the far red one is lost
  // behind it in the given order, and sorted far to near it shows through.
  const Json writes = alg.open(j, Numeric::exact).run();
  CHECK(writes["painter"] == Json{1, 0});
  CHECK(writes["differ"].get<std::int64_t>() > 0);
  // Without depth writes both orders draw every fragment, yet over is not commutative: the
  // overlap still differs.
  j["depth_write"] = false;
  const Json no_writes = alg.open(j, Numeric::exact).run();
  CHECK(no_writes["differ"].get<std::int64_t>() > 0);
  // Listed far to near already, the two orders are one order: no pixel differs.
  std::swap(j["triangles"][0], j["triangles"][1]);
  j["depth_write"] = true;
  const Json sorted = alg.open(j, Numeric::exact).run();
  CHECK(sorted["painter"] == Json{0, 1});
  CHECK(sorted["differ"] == 0);
}

TEST_CASE("fog: every exact and reference step against GL's formulas", "[pipeline][fog][steps]") {
  int linear = 0, exps = 0, clamped = 0;
  for (Json j : inputs_with("fog", "fog")) {
    for (const char* mode : {"linear", "exp", "exp2"}) {
      j["fog"]["mode"] = mode;
      if (std::string(mode) == "linear" && !j["fog"].contains("end")) j["fog"]["start"] = 5, j["fog"]["end"] = 35;
      INFO(j.dump());
      const Json& f = j["fog"];
      pipe::FogParams<Rational> p{std::string(mode) == "linear" ? pipe::FogMode::linear : std::string(mode) == "exp" ? pipe::FogMode::exp : pipe::FogMode::exp2,
                                  f.contains("start") ? q_of(f["start"]) : Rational(0), f.contains("end") ? q_of(f["end"]) : Rational(1),
                                  f.contains("density") ? q_of(f["density"]) : Rational(1), point_of(f["rgb"])};
      std::vector<pipe::Fragment<Rational>> frags;
      for (const Json& q : j["fragments"]) frags.push_back({q_of(q["c"]), point_of(q["rgb"])});
      Recorder<Rational> rec;
      (void)pipe::fog<Rational>(p, frags, rec);
      std::size_t i = 0;
      Rational factor;
      for_each_step<pipe::FogAlgo>(rec, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry&) {
        const auto& q = frags[std::min(i, frags.size() - 1)];
        if (line == "fragment") {
          i = static_cast<std::size_t>(sv["i"].get_num().get_si());
          REQUIRE(i < frags.size());
          CHECK(sv["c"] == frags[i].c);
          CHECK((Vec3<Rational>{sv["C.r"], sv["C.g"], sv["C.b"]} == frags[i].rgb));
        } else if (line == "linear") {
          factor = (p.end - q.c) / (p.end - p.start);
          CHECK(sv["f"] == factor);
          ++linear;
        } else if (line == "exp" || line == "exp2") {
          // Unclamped: e^(-x) <= 1 for x >= 0, so the oracle's clamped factor is the same number.
          factor = po::fog_factor(line == "exp" ? 1 : 2, p.start, p.end, p.density, q.c);
          CHECK(close_to(sv["f"], factor));
          ++exps;
        } else if (line == "clamp") {
          const Rational want = std::clamp(factor, Rational(0), Rational(1));
          clamped += want != factor;
          CHECK(close_to(sv["f"], want));
          factor = sv["f"];
        } else if (line == "colour") {
          const Vec3<Rational> want = Vec3<Rational>(factor * q.rgb) + Vec3<Rational>(Rational(1 - factor) * p.rgb);
          CHECK(sv["C'.r"] == want.x);
          CHECK(sv["C'.g"] == want.y);
          CHECK(sv["C'.b"] == want.z);
        } else {
          FAIL("unexpected line " << line);
        }
      });
    }
  }
  CHECK(linear >= 5);
  CHECK(exps >= 10);
  CHECK(clamped >= 1);
}
