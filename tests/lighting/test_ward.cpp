// Ward's isotropic term: hand-computed values, Helmholtz reciprocity of its BRDF, and the reference
// run against the oracle's angle formula (oracle/lighting_oracle.cpp) on random frames.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include "catalog.hpp"

using namespace sw;

namespace {

double ward(const Json& in, Numeric n) { return find_algorithm("ward").open(in, n).run()["value"].get<double>(); }

}  // namespace

TEST_CASE("ward: hand-computed terms in every mode and from the oracle", "[lighting][ward]") {
  // Light, eye and normal together: h = n, tan = 0, so s = sqrt(1/1) / (4 m^2) = 1 at m = 1/2.
  const Json head_on = Json::parse(R"({"n":[0,0,1],"l":[0,0,2],"e":[0,0,1],"m":"1/2"})");
  // l = n, e = (3, 0, 4)/5: n.h = sqrt(9/10), tan^2 = 1/9 = m^2 at m = 1/3, so s = e^-1 sqrt(5/4) / (4/9).
  const Json tilted = Json::parse(R"({"n":[0,0,1],"l":[0,0,1],"e":[3,0,4],"m":"1/3"})");
  const double tilted_s = 9 * std::sqrt(1.25) / (4 * std::exp(1.0));
  for (Numeric n : {Numeric::f32, Numeric::f64, Numeric::reference}) {
    INFO(numeric_name(n));
    CHECK(ward(head_on, n) == 1.0);
    CHECK(ward(tilted, n) == Approx(tilted_s).epsilon(n == Numeric::f32 ? 1e-5 : n == Numeric::f64 ? 1e-13 : 1e-15));
  }
  CHECK(find_algorithm("ward").open(tilted, Numeric::reference).oracle()["value"].get<double>() == Approx(tilted_s).epsilon(1e-15));
}

TEST_CASE("ward: reciprocity, and the reference against the oracle on random frames", "[lighting][ward]") {
  std::mt19937_64 rng(1992);
  std::normal_distribution<double> g;
  auto dir = [&](double up) { return Json::array({g(rng), g(rng), std::fabs(g(rng)) + up}); };
  int compared = 0;
  for (int k = 0; k < 200; ++k) {
    Json in = {{"n", Json::array({0, 0, 1})}, {"l", dir(0.05)}, {"e", dir(0.05)}, {"m", std::uniform_real_distribution<double>(0.05, 1)(rng)}};
    INFO(in.dump());
    const Json a = find_algorithm("ward").open(in, Numeric::f64).run();
    std::swap(in["l"], in["e"]);
    const Json b = find_algorithm("ward").open(in, Numeric::f64).run();
    // The BRDF s / (n.l) is symmetric in l and e.
    CHECK(a["value"].get<double>() / a["nl"].get<double>() == Approx(b["value"].get<double>() / b["nl"].get<double>()).epsilon(1e-12));
    const Run ref = find_algorithm("ward").open(in, Numeric::reference);
    CHECK(ref.run()["value"].get<double>() == Approx(ref.oracle()["value"].get<double>()).epsilon(1e-15));
    ++compared;
  }
  CHECK(compared == 200);
}
