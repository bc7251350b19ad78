// z-buffer: every exact step against closed forms and the fill family's oracle, the final image
// against the brute-force oracle (oracle/pipeline_oracle.cpp), and the claims of its semantics:
// coplanar triangles tie exactly (GL_LESS keeps the first everywhere, GL_LEQUAL the last) where
// float fights; 16 bits merge near-coplanar triangles that 24 bits keep apart; glPolygonOffset
// separates them.
#include <catch2/catch.hpp>
#include <map>
#include "catalog.hpp"
#include "corpus.hpp"
#include "fill_oracle.hpp"
#include "pipeline/z_buffer.hpp"
#include "pipeline_oracle.hpp"
#include "pipeline_test_support.hpp"
#include "run.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::pipeline;
namespace po = sw::pipeline_oracle;

namespace {

struct ZScene {
  std::int64_t w = 0, h = 0;
  std::vector<po::DepthTriangle> tris;
  int bits = 0;
  bool lequal = false;
  Rational clear = 1;
};

ZScene scene_of(const Json& j) {
  ZScene s;
  s.w = j["size"][0].get<std::int64_t>(), s.h = j["size"][1].get<std::int64_t>();
  s.bits = j.value("depth_bits", 0);
  s.lequal = j.value("depth_func", std::string("less")) == "lequal";
  if (j.contains("clear_depth")) s.clear = q_of(j["clear_depth"]);
  s.tris = window_triangles_of(j);
  return s;
}

Rational quantized(const Rational& z, int bits) {
  if (bits == 0) return z;
  const Rational x = z * Rational((mpz_class(1) << bits) - 1) + Rational(1, 2);
  mpz_class f;
  mpz_fdiv_q(f.get_mpz_t(), x.get_num_mpz_t(), x.get_den_mpz_t());
  return Rational(f);
}

std::vector<Json> z_inputs() {
  std::vector<Json> out{Json::parse(find_algorithm("z-buffer").example)};
  for (const Json& j : corpus("pipeline"))
    if (j.contains("size") && j.contains("triangles")) out.push_back(j);
  return out;
}

// The run's result for input j in mode n.
Json result_of(const Json& j, Numeric n) { return find_algorithm("z-buffer").open(j, n).run(); }

}  // namespace

TEST_CASE("z-buffer: every exact step against closed forms, the image against the brute-force oracle", "[pipeline][zbuffer][steps]") {
  int fragments = 0, ties = 0, offsets = 0;
  for (const Json& j : z_inputs()) {
    INFO(j.dump());
    const ZScene sc = scene_of(j);
    std::vector<pipe::DepthTriangle<Rational>> tris;
    for (const auto& t : sc.tris) {
      pipe::DepthTriangle<Rational> d;
      for (int k = 0; k < 3; ++k) d.v[k] = {t.v[k][0], t.v[k][1], t.v[k][2]};
      d.id = t.id, d.factor = t.factor, d.units = t.units;
      tris.push_back(d);
    }
    Recorder<Rational> rec;
    const auto got = pipe::z_buffer<Rational>(sc.w, sc.h, tris, sc.bits, sc.lequal ? pipe::DepthFunc::lequal : pipe::DepthFunc::less, sc.clear, rec);
    const po::DepthImage want = po::z_buffer(sc.w, sc.h, sc.tris, sc.bits, sc.lequal, sc.clear);
    CHECK(got.id == want.ids);
    CHECK(got.depth == want.depth);
    CHECK(got.fragments == want.fragments);
    CHECK(got.ties == want.ties);
    // The steps: the buffer as the trace itself wrote it, each value against its closed form.
    std::map<std::pair<std::int64_t, std::int64_t>, Rational> buffer;
    const po::DepthTriangle* t = nullptr;
    Rational o, d_frag;
    std::int64_t fi = 0, fj = 0;
    const Rational r = sc.bits == 0 ? Rational(1, 1 << 24) : Rational(1) / Rational((mpz_class(1) << sc.bits) - 1);
    for_each_step<pipe::ZBuffer>(rec, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
      if (line == "clear") {
        CHECK(sv["clear"] == quantized(sc.clear, sc.bits));
        CHECK(sv["r"] == r);
      } else if (line == "plane") {
        const std::int64_t id = sv["t"].get_num().get_si();
        t = nullptr;
        for (const auto& x : sc.tris)
          if (x.id == id) t = &x;
        REQUIRE(t);
        const auto& v = t->v;
        const Rational area2 = (v[1][0] - v[0][0]) * (v[2][1] - v[0][1]) - (v[1][1] - v[0][1]) * (v[2][0] - v[0][0]);
        CHECK(sv["area2"] == area2);
        if (sgn(area2) == 0) return;
        // The slopes: the depth's change along x and y, from the fill oracle's linear interpolation.
        const std::array<Vec2<Rational>, 3> xy{Vec2<Rational>{v[0][0], v[0][1]}, {v[1][0], v[1][1]}, {v[2][0], v[2][1]}};
        const std::array<Rational, 3> zs{v[0][2], v[1][2], v[2][2]};
        CHECK(sv["zx"] == oracle::linear_at(xy, zs, Pixel{1, 0}) - oracle::linear_at(xy, zs, Pixel{0, 0}));
        CHECK(sv["zy"] == oracle::linear_at(xy, zs, Pixel{0, 1}) - oracle::linear_at(xy, zs, Pixel{0, 0}));
        CHECK(g.take(GeoKind::polygon).values.size() == 6);
      } else if (line == "offset") {
        o = sv["o"];
        offsets += sgn(o) != 0;
        // glPolygonOffset: factor times the steeper slope, plus units times r.
        const std::array<Vec2<Rational>, 3> xy{Vec2<Rational>{t->v[0][0], t->v[0][1]}, {t->v[1][0], t->v[1][1]}, {t->v[2][0], t->v[2][1]}};
        const std::array<Rational, 3> zs{t->v[0][2], t->v[1][2], t->v[2][2]};
        const Rational base = oracle::linear_at(xy, zs, Pixel{0, 0});
        const Rational zx = abs(Rational(oracle::linear_at(xy, zs, Pixel{1, 0}) - base)), zy = abs(Rational(oracle::linear_at(xy, zs, Pixel{0, 1}) - base));
        CHECK(o == t->factor * std::max(zx, zy) + t->units * r);
      } else if (line == "cover") {
        const std::array<Vec2<Rational>, 3> xy{Vec2<Rational>{t->v[0][0], t->v[0][1]}, {t->v[1][0], t->v[1][1]}, {t->v[2][0], t->v[2][1]}};
        CHECK(sv["samples"] == Rational(std::int64_t(po::window_samples(t->v, sc.w, sc.h).size())));
      } else if (line == "fragment") {
        fi = sv["i"].get_num().get_si(), fj = sv["j"].get_num().get_si();
        const std::array<Vec2<Rational>, 3> xy{Vec2<Rational>{t->v[0][0], t->v[0][1]}, {t->v[1][0], t->v[1][1]}, {t->v[2][0], t->v[2][1]}};
        Rational z = oracle::linear_at(xy, {t->v[0][2], t->v[1][2], t->v[2][2]}, Pixel{fi, fj}) + o;
        z = std::clamp(z, Rational(0), Rational(1));
        CHECK(sv["z"] == z);
        d_frag = quantized(z, sc.bits);
        CHECK(sv["d"] == d_frag);
        ++fragments;
      } else if (line == "test") {
        const auto it = buffer.find({fi, fj});
        const Rational cell = it == buffer.end() ? quantized(sc.clear, sc.bits) : it->second;
        CHECK(sv["d"] == d_frag);
        CHECK(sv["depth"] == cell);
        CHECK(sv["pass"] == int(sc.lequal ? d_frag <= cell : d_frag < cell));
        ties += d_frag == cell;
      } else if (line == "write") {
        buffer[{fi, fj}] = d_frag;
        CHECK(sv["id"] == Rational(t->id));
        GeoItem& p = g.take(GeoKind::pixel);
        CHECK(p.values == std::vector<Rational>{Rational(fi), Rational(fj)});
        CHECK(p.value == Rational(t->id));
      } else if (line == "done") {
        CHECK(sv["passed"] == Rational(want.passed));
        CHECK(sv["ties"] == Rational(want.ties));
      } else {
        FAIL("unexpected line " << line);
      }
    });
  }
  CHECK(fragments >= 300);
  CHECK(ties >= 20);
  CHECK(offsets >= 1);
}

TEST_CASE("z-buffer: coplanar triangles tie exactly, float fights, 16 bits merge and the offset separates", "[pipeline][zbuffer]") {
  const Json example = Json::parse(find_algorithm("z-buffer").example);
  // Exact: triangles 2 and 3 lie in the plane of 0 and 1, so every depth ties and GL_LESS keeps 0 and 1.
  const Json exact = result_of(example, Numeric::exact);
  for (const Json& id : exact["ids"]) CHECK((id == 0 || id == 1));
  CHECK(exact["ties"].get<std::int64_t>() > 0);
  // GL_LEQUAL keeps the later triangles instead.
  Json leq = example;
  leq["depth_func"] = "lequal";
  const Json leq_result = result_of(leq, Numeric::exact);
  for (const Json& id : leq_result["ids"]) CHECK((id == 2 || id == 3));
  // Float's rounded depths do not tie everywhere: some pixels go to the later triangles.
  int later = 0;
  const Json float_result = result_of(example, Numeric::f32);
  for (const Json& id : float_result["ids"]) later += id == 2 || id == 3;
  CHECK(later > 0);
  // Near-coplanar: triangles 2 and 3 lie 2^-20 nearer. 24 bits see it, 16 bits do not.
  Json near = example;
  for (int t = 2; t < 4; ++t)
    for (int k = 0; k < 3; ++k) near["triangles"][t]["v"][k][2] = (q_of(near["triangles"][t]["v"][k][2]) - Rational(1, 1 << 20)).get_str();
  near["depth_bits"] = 24;
  const Json bits24 = result_of(near, Numeric::exact);
  for (const Json& id : bits24["ids"]) CHECK((id == 2 || id == 3));
  near["depth_bits"] = 16;
  const Json bits16 = result_of(near, Numeric::exact);
  int kept = 0;
  for (const Json& id : bits16["ids"]) kept += id == 0 || id == 1;
  CHECK(kept > 0);
  // glPolygonOffset(0, -2) on the nearer pair: two units of 16 bits bring them in front again.
  for (int t = 2; t < 4; ++t) near["triangles"][t]["offset"] = {0, -2};
  const Json offset = result_of(near, Numeric::exact);
  for (const Json& id : offset["ids"]) CHECK((id == 2 || id == 3));
}
