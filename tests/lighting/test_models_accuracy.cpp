// Float and double against the MPFR oracle. Stated tolerances, on frames of small exact rationals
// that are not ill-conditioned (n.l, n.e >= 1/8; for phong r.e >= 1/8 where the eye is on the
// mirror side): |got - oracle| <= 2^-44 (double) or 2^-14 (float) times (1 + shininess) times
// max(|oracle|, 1/16). The hard-case corpus: reference equals the oracle (2^-200), and every mode
// takes the oracle's decisions; float and double failures (NaN, negative, above 1) are counted and
// printed, not asserted away (docs/lighting/accuracy.md has the bench's counts).
#include <catch2/catch.hpp>
#include <cmath>
#include "catalog.hpp"
#include "lighting_test_support.hpp"

using namespace sw;
using namespace sw::testing::lighting_models;

namespace {

double rel_err(double got, const Q& want, double floor) {
  return std::fabs(got - want.get_d()) / std::max(std::fabs(want.get_d()), floor);
}

}  // namespace

TEST_CASE("lighting: float and double stay within the stated tolerances of the oracle on well-conditioned frames", "[lighting][accuracy]") {
  for (const char* id : kIds) {
    Gen gen(31 + std::string_view(id).size());
    double worst_d = 0, worst_f = 0;
    int used = 0;
    for (int k = 0; k < 400 && used < 150; ++k) {
      const ModelInput in = lighting_io::parse_model_input(id, gen.input(id));
      const auto o = oracle_of(id, in);
      if (!(o.lit && o.seen) || o.named.at("nl") < Q(1, 8) || o.named.at("ne") < Q(1, 8)) continue;
      if (std::string_view(id) == "phong" && o.named.at("front") == 1 && o.named.at("c") < Q(1, 8)) continue;
      ++used;
      const double scale = 1 + in.p.shininess.get_d();
      INFO(id << " " << lighting_io::to_json(in).dump() << " oracle " << o.value.get_d());
      const double ed = rel_err(run_model<double>(id, in), o.value, 1.0 / 16) / scale;
      const double ef = rel_err(run_model<float>(id, in), o.value, 1.0 / 16) / scale;
      CHECK(ed <= std::ldexp(1.0, -44));
      CHECK(ef <= std::ldexp(1.0, -14));
      worst_d = std::max(worst_d, ed), worst_f = std::max(worst_f, ef);
    }
    INFO(id << ": worst scaled relative error double " << worst_d << ", float " << worst_f);
    CHECK(used >= 50);
  }
}

TEST_CASE("lighting: the hard-case corpus, reference equal to the oracle and every mode on the oracle's decisions", "[lighting][accuracy][corpus]") {
  int fails_f = 0, fails_d = 0, cases = 0;
  for (const CorpusCase& c : corpus()) {
    INFO(c.algorithm << ": " << c.name << " " << c.input.dump());
    const Algorithm& alg = find_algorithm(c.algorithm);
    const ModelInput in = lighting_io::parse_model_input(c.algorithm, c.input);
    const auto o = oracle_of(c.algorithm, in);
    ++cases;
    CHECK(in.signs.lit == o.lit);
    CHECK(in.signs.seen == o.seen);
    const Q ref = run_model<Q>(c.algorithm, in);
    CHECK(close(ref, o.value));
    CHECK(sgn(ref) >= 0);
    for (const char* mode : {"float", "double", "reference"}) {
      const Json r = alg.open(c.input, *parse_numeric(mode)).run();
      CHECK(r.at("lit") == o.lit);
      CHECK(r.at("seen") == o.seen);
      if (std::string_view(mode) == "reference") CHECK(!r.contains("failure"));
      else if (r.contains("failure")) (std::string_view(mode) == "float" ? fails_f : fails_d)++;
    }
  }
  CHECK(cases > 150);
  INFO("hard corpus: " << cases << " cases; float failures " << fails_f << ", double failures " << fails_d);
  CHECK(fails_f >= fails_d);  // the denormal and tiny-length cases fail in float at least where double does
}
