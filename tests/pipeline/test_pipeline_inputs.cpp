// Bad input to the pipeline family: every case of tests/cases/pipeline/bad_inputs.jsonl is refused
// with one line that names the field ("names"), in every mode; and the camera's exactness rule:
// exact and filtered modes refuse a camera with an irrational frame, saying so, and reference takes it.
#include <catch2/catch.hpp>
#include <fstream>
#include "catalog.hpp"
#include "run.hpp"

using namespace sw;

TEST_CASE("pipeline: bad inputs are refused with one line naming the field", "[pipeline][inputs]") {
  std::ifstream in(std::string(SW_SOURCE_DIR) + "/tests/cases/pipeline/bad_inputs.jsonl");
  std::string line;
  int cases = 0;
  while (std::getline(in, line)) {
    const Json c = Json::parse(line);
    const Algorithm& alg = find_algorithm(c["algorithm"].get<std::string>());
    INFO(c["algorithm"].get<std::string>() << ": " << c["why"].get<std::string>());
    for (Numeric n : alg.numerics) {
      try {
        (void)alg.open(c["input"], n);
        FAIL("accepted in " << numeric_name(n));
      } catch (const InputError& e) {
        const std::string msg = e.what();
        CHECK(msg.find('\n') == std::string::npos);
        CHECK(msg.find(c["names"].get<std::string>()) != std::string::npos);
      }
    }
    ++cases;
  }
  CHECK(cases >= 30);
}

TEST_CASE("pipeline: exact and filtered refuse an irrational camera frame, reference takes it", "[pipeline][inputs]") {
  Json j = Json::parse(find_algorithm("transform").example);
  j["camera"]["eye"] = {1, 2, 3};  // |target - eye|^2 = 14
  for (const char* id : {"transform", "backface-cull", "frustum-cull"}) {
    const Algorithm& alg = find_algorithm(id);
    Json k = Json::parse(alg.example);
    k["camera"] = j["camera"];
    INFO(id);
    for (Numeric n : {Numeric::exact, Numeric::filtered}) {
      try {
        (void)alg.open(k, n);
        FAIL("accepted in " << numeric_name(n));
      } catch (const InputError& e) {
        CHECK(std::string(e.what()).find("irrational") != std::string::npos);
      }
    }
    CHECK_NOTHROW(alg.open(k, Numeric::reference).run());
    CHECK_NOTHROW(alg.open(k, Numeric::f32).run());
  }
}
