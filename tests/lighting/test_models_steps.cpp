// The reflection models step by step in reference mode: every variable and geometry item every step
// records (the nested diffuse model inside toon included), against the oracle's quantity of the same
// name (oracle/lighting_oracle.cpp: 400-bit MPFR from the papers' angle formulas), within 2^-200
// relative plus 2^-250 absolute (gaussian's angle: 2^-140, as acos near 1 halves the bits); decisions (lit, seen, front, above) exactly. Inputs: each entry's
// example, the hard-case corpus and seeded random frames of small exact rationals.
#include <catch2/catch.hpp>
#include <set>
#include "catalog.hpp"
#include "lighting_test_support.hpp"
#include "step_values.hpp"

using namespace sw;
using namespace sw::testing;
using namespace sw::testing::lighting_models;

namespace {

// One step against the oracle's named quantities.
void check_step(const lighting_oracle::OracleTerm& o, StepValues& sv, StepGeometry& g) {
  std::vector<std::string> names;
  for (const auto& kv : sv.v) names.push_back(kv.first);
  for (const std::string& name : names) {
    INFO("variable " << name << " = " << sv.v.at(name).get_d());
    const auto it = o.named.find(name);
    REQUIRE(it != o.named.end());
    INFO("oracle " << it->second.get_d());
    if (name == "lit" || name == "seen" || name == "front" || name == "above") CHECK(sv[name] == it->second);
    // acos(c) near c = 1 turns the reference's 2^-300 in c into 2^-150 in the angle.
    else if (name == "alpha") CHECK(close(sv[name], it->second, 200, 140));
    else CHECK(close(sv[name], it->second));
  }
  for (GeoItem& item : g.items) {
    item.checked = true;
    INFO("geometry " << item.label);
    if (item.kind == GeoKind::plane) {  // the tangent plane at the point: through the origin, normal n
      CHECK(item.life == "keep");
      REQUIRE(item.values.size() == 6);
      for (int k = 0; k < 3; ++k) CHECK(sgn(item.values[k]) == 0);
      for (int k = 0; k < 3; ++k) CHECK(close(item.values[3 + k], o.named.at(std::string("n.") + "xyz"[k])));
      continue;
    }
    CHECK(item.kind == GeoKind::segment3);
    CHECK(item.life == "keep");
    REQUIRE(item.values.size() == 6);
    for (int k = 0; k < 3; ++k) CHECK(sgn(item.values[k]) == 0);
    const std::set<std::string> labels = {"n", "l", "e", "h", "r"};
    REQUIRE(labels.count(item.label));
    for (int k = 0; k < 3; ++k) CHECK(close(item.values[3 + k], o.named.at(item.label + "." + "xyz"[k])));
  }
}

}  // namespace

TEST_CASE("lighting: every reference step value of the nine models matches the MPFR oracle", "[lighting][steps][replay]") {
  const auto corp = corpus();
  for (const char* id : kIds) {
    const Algorithm& alg = find_algorithm(id);
    std::vector<Json> inputs = {Json::parse(alg.example)};
    for (const CorpusCase& c : corp)
      if (c.algorithm == id) inputs.push_back(c.input);
    Gen gen(900 + std::string_view(id).size());
    for (int k = 0; k < 40; ++k) inputs.push_back(gen.input(id));
    std::set<std::string_view> reached;
    int lit = 0, dark = 0;
    for (const Json& j : inputs) {
      INFO(id << " " << j.dump());
      const ModelInput in = lighting_io::parse_model_input(id, j);
      const auto o = oracle_of(id, in);
      Recorder<Q> t;
      const Q value = run_model<Q>(id, in, t);
      CHECK(close(value, o.value));
      CHECK(in.signs.lit == o.lit);
      CHECK(in.signs.seen == o.seen);
      (o.lit && o.seen ? lit : dark)++;
      with_algo(id, [&]<class A>(std::type_identity<A>) {
        for_each_step<A>(
            t, [&](std::size_t, std::string_view line, StepValues& sv, StepGeometry& g) {
              reached.insert(line);
              check_step(o, sv, g);
            },
            [&](std::size_t s) {  // toon's nested diffuse model
              StepValues sv = values_of(t, s);
              StepGeometry g = geometry_of(t, s);
              check_step(o, sv, g);
              require_all_checked(sv, s);
            });
        return 0;
      });
    }
    with_algo(id, [&]<class A>(std::type_identity<A>) {
      for (const ListingLine& l : A::listing().lines) {
        INFO(id << ": line " << l.name << " never reached");
        CHECK(reached.count(l.name));
      }
      return 0;
    });
    CHECK(lit > 10);
    CHECK(dark > 0);
  }
}

TEST_CASE("lighting: the dispatchers shade calls give each model's term, in the model's nested listing", "[lighting][steps][dispatch]") {
  for (const char* id : kIds) {
    Gen gen(300 + std::string_view(id).size());
    int lit = 0;
    for (int k = 0; k < 30; ++k) {
      const ModelInput in = lighting_io::parse_model_input(id, gen.input(id));
      INFO(id << " " << lighting_io::to_json(in).dump());
      Recorder<double> t;
      const auto f = lighting::shading_frame<lighting::Lambert>(to_num<double>(in.n), to_num<double>(in.l), to_num<double>(in.e), t);
      const std::size_t frame_steps = t.size();
      CHECK(frame_steps == 2);
      const auto p = params_as<double>(in.p);
      const double got = in.choice.specular ? lighting::specular_term(in.choice.spec, f, p, t) : lighting::diffuse_term(in.choice.diffuse, f, p, t);
      CHECK(got == run_model<double>(id, in));  // decisions made in the frame (exact on the double input) equal the input's here
      lit += f.lit && f.seen;
      if (!(f.lit && f.seen)) CHECK(t.size() == frame_steps);  // below the horizon: 0 and no step
      for (std::size_t s = frame_steps; s < t.size(); ++s) {
        CHECK(t.at(s).scope != 0);
        CHECK(t.scope_id(t.at(s).scope) == (t.at(s).scope == 1 ? std::string_view(id) : std::string_view(lighting::model_name(in.choice.diffuse))));
      }
    }
    CHECK(lit > 5);
  }
}
