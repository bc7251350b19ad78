// The probes' vocabulary beyond scalars: vector, colour and list variables and the geometry
// modifiers, as the Recorder stores them and as the JSONL probe writes them; and what `check`
// accepts as a variable's shape.
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include "core/jsonl_probe.hpp"
#include "core/probe.hpp"
#include "trace_io.hpp"

using namespace sw;

TEST_CASE("probe: colour and list variables keep their shape in memory and in JSONL", "[probe]") {
  const Vec3<Rational> rgb{Rational(1, 2), 0, 1};
  const std::vector<Rational> row = {Rational(3), Rational(-1, 4)};
  const std::vector<std::int64_t> stack = {7, 3, 0};
  Recorder<Rational> r;
  r.step(1, StepKind::visit).colour("c", rgb).list("row", row).ilist("stack", stack).ilist("empty", {});
  REQUIRE(r.size() == 1);
  REQUIRE(r.at(0).var_end - r.at(0).var_begin == 4);
  const VarRecord &c = r.var_at(0), &l = r.var_at(1), &s = r.var_at(2), &e = r.var_at(3);
  CHECK(c.shape == VarShape::colour);
  CHECK(r.value_text(c) == "rgb(1/2, 0, 1)");
  CHECK(l.shape == VarShape::list);
  CHECK_FALSE(l.is_int);
  CHECK(r.value_text(l) == "[3, -1/4]");
  CHECK(s.is_int);
  CHECK(r.value_text(s) == "[7, 3, 0]");
  CHECK(r.component_double(s, 1) == 3);
  CHECK(e.count == 0);
  CHECK(r.value_text(e) == "[]");
  CHECK(r.value_double(e) == 0);

  std::ostringstream out;
  {
    JsonlProbe<Rational> j(out);
    j.step(1, StepKind::visit).colour("c", rgb).list("row", row).ilist("stack", stack);
  }
  const Json line = Json::parse(out.str());
  CHECK(line["vars"]["c"] == Json::parse(R"({"rgb":["1/2","0","1"]})"));
  CHECK(line["vars"]["row"] == Json::parse(R"(["3","-1/4"])"));
  CHECK(line["vars"]["stack"] == Json::parse("[7,3,0]"));

  // Lists are short by contract: a 65th entry is refused, not truncated.
  const std::vector<std::int64_t> long_list(kMaxListLength + 1, 1);
  CHECK_THROWS_AS(r.step(2, StepKind::visit).ilist("stack", long_list), std::length_error);
  std::ostringstream out2;
  JsonlProbe<Rational> j2(out2);
  CHECK_THROWS_AS(j2.step(1, StepKind::visit).ilist("stack", long_list), std::length_error);
}

TEST_CASE("probe: geometry modifiers label, keep, replace and value the item just emitted", "[probe]") {
  Recorder<Rational> r;
  r.step(1, StepKind::init).segment(Vec2<Rational>{0, 0}, Vec2<Rational>{1, 2}).label("edge").value(Rational(-3)).keep()
      .point(Vec2<Rational>{1, 1}).replace();
  const GeoRecord &a = r.geo_at(0), &b = r.geo_at(1);
  CHECK(a.kind == GeoKind::segment2);
  CHECK(std::string(a.label) == "edge");
  CHECK(a.life == Life::keep);
  CHECK(r.geo_value(a) == -3.0);
  CHECK(b.kind == GeoKind::point2);
  CHECK(b.label == nullptr);
  CHECK(b.life == Life::replace);
  CHECK_FALSE(r.geo_value(b));

  std::ostringstream out;
  {
    JsonlProbe<Rational> j(out);
    j.step(1, StepKind::init).segment(Vec2<Rational>{0, 0}, Vec2<Rational>{1, 2}).label("edge").value(Rational(-3)).keep();
  }
  CHECK(Json::parse(out.str())["geo"][0] == Json::parse(R"({"segment":["0","0","1","2"],"label":"edge","value":"-3","life":"keep"})"));
}

// The JSONL probe reuses the text of recently written doubles; every number must still read back
// as its own bits, whichever mix of repeats, evictions, signed zeros and non-finite values comes.
template <class Num> static void check_numbers_read_back() {
  std::mt19937_64 rng(7);
  std::vector<Num> pool = {Num(0.0), Num(-0.0), Num(0.1), -std::numeric_limits<Num>::max(), std::numeric_limits<Num>::denorm_min(),
                           Num(1.0 / 3.0)};
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  for (int i = 0; i < 6; ++i) pool.push_back(Num(u(rng)));
  std::vector<Num> written;
  std::ostringstream out;
  {
    JsonlProbe<Num> j(out);
    for (int n = 0; n < 2000; ++n) {
      const Num a = pool[rng() % pool.size()], b = pool[rng() % pool.size()];
      j.step(1, StepKind::visit).num("a", a).point(Vec2<Num>{a, b}).value(b);
      written.insert(written.end(), {a, a, b, b});
    }
    j.step(2, StepKind::done).num("nan", Num(NAN)).num("inf", Num(INFINITY)).num("zero", Num(-0.0));
  }
  // Read with strtod (through sscanf), not the JSON library, which reads "-0" as the integer 0.
  std::istringstream in(out.str());
  std::size_t k = 0;
  auto same_bits = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  for (std::string line; std::getline(in, line);) {
    double got[4];
    if (std::sscanf(line.c_str(), R"({"step":%*d,"line":1,"kind":"visit","vars":{"a":%lf},"geo":[{"point":[%lf,%lf],"value":%lf}]})",
                    &got[0], &got[1], &got[2], &got[3]) != 4) {
      const Json j = Json::parse(line);
      CHECK(j["vars"]["nan"] == "NaN");
      CHECK(j["vars"]["inf"] == "Infinity");
      CHECK_THAT(line, Catch::Contains(R"("zero":-0})"));
      continue;
    }
    for (double g : got) REQUIRE(same_bits(g, static_cast<double>(written[k++])));
  }
  CHECK(k == written.size());
}

TEST_CASE("probe: JSONL numbers read back bit for bit through the probe's text reuse", "[probe]") {
  check_numbers_read_back<double>();
  check_numbers_read_back<float>();
}

TEST_CASE("probe: check reads colour and list variables and refuses malformed ones", "[probe][check]") {
  // A dda-line trace with one variable added: well formed (exit 1, not recorded by the algorithm)
  // or malformed (exit 2).
  std::stringstream s;
  write_trace(find_algorithm("dda-line").open(Json::parse(R"({"p0":[0,0],"p1":[3,1]})"), Numeric::exact), s);
  std::vector<Json> lines;
  for (std::string l; std::getline(s, l);) lines.push_back(Json::parse(l));
  auto check_with = [&](const char* var) {
    auto t = lines;
    t[1]["vars"]["extra"] = Json::parse(var);
    std::stringstream in;
    for (const Json& l : t) in << l.dump() << '\n';
    return check_trace(in);
  };
  for (const char* ok : {R"({"rgb":["1/2",0,1]})", "[1,2,3,4,5]", "[]", R"(["1/3",2])"}) {
    INFO(ok);
    const CheckReport rep = check_with(ok);
    CHECK(rep.status == 1);
    CHECK_THAT(rep.message, Catch::Contains("variable extra"));
  }
  for (const char* bad : {R"({"rgb":[1,2]})", R"({"hsv":[1,2,3]})", R"([[1]])", R"(["x"])"}) {
    INFO(bad);
    CHECK(check_with(bad).status == 2);
  }
}

TEST_CASE("probe: a tree node records its id, its parent and its bounds", "[probe]") {
  Recorder<Rational> r;
  r.step(1, StepKind::visit).node(5, 2, Vec2<Rational>{0, Rational(1, 2)}, Vec2<Rational>{4, 8}).node(1, -1, Vec3<Rational>{0, 0, 0}, Vec3<Rational>{1, 2, 3});
  const GeoRecord &a = r.geo_at(0), &b = r.geo_at(1);
  CHECK(a.kind == GeoKind::node2);
  CHECK(geo_name(a.kind) == "node");
  REQUIRE(a.count == 6);
  const Rational want2[6] = {5, 2, 0, Rational(1, 2), 4, 8};
  for (int k = 0; k < 6; ++k) CHECK(r.num_value(a.slot + k) == want2[k]);
  CHECK(b.kind == GeoKind::node3);
  REQUIRE(b.count == 8);
  CHECK(r.num_value(b.slot + 1) == -1);
  CHECK(r.num_value(b.slot + 7) == 3);
}
