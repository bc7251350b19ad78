// The ray step tests call the algorithm headers directly (so that a test built against a changed
// copy of them tests the change); the catalog's recording must be that same trace, step for step.
// And `stepwise check` on exact ray traces.
#include <catch2/catch.hpp>
#include <sstream>
#include "catalog.hpp"
#include "ray_steps.hpp"
#include "trace_io.hpp"

using namespace sw;
using namespace sw::testing::rays;

TEST_CASE("rays: exact step replay, the catalog records what the headers record", "[rays][steps]") {
  int compared = 0;
  for (const Algorithm& alg : catalog()) {
    if (alg.family != "rays") continue;
    const bool reference = alg.id == "camera-ray" || alg.id == "sphere-uv";
    std::vector<Case> cases = example_and_lessons(alg.id);
    for (Case& c : corpus_cases("")) cases.push_back(std::move(c));
    for (const Case& c : cases) {
      try {
        (void)alg.open(c.input, reference ? Numeric::reference : Numeric::exact);
      } catch (const InputError&) {
        continue;  // another primitive's case
      }
      INFO(alg.id << ", " << c.name);
      const Recorded rec = alg.open(c.input, reference ? Numeric::reference : Numeric::exact).record();
      const auto& a = dynamic_cast<const Recorder<Q>&>(*rec.trace);
      Recorder<Q> b;
      record_direct(alg.id, c.input, b);
      ++compared;
      REQUIRE(a.size() == b.size());
      for (std::size_t s = 0; s < a.size(); ++s) {
        INFO("step " << s);
        CHECK(a.at(s).line == b.at(s).line);
        CHECK(a.at(s).kind == b.at(s).kind);
        const auto va = sw::testing::values_of(a, s), vb = sw::testing::values_of(b, s);
        CHECK(va.v == vb.v);
        const auto ga = sw::testing::geometry_of(a, s), gb = sw::testing::geometry_of(b, s);
        REQUIRE(ga.items.size() == gb.items.size());
        for (std::size_t k = 0; k < ga.items.size(); ++k) {
          CHECK(ga.items[k].kind == gb.items[k].kind);
          CHECK(ga.items[k].values == gb.items[k].values);
          CHECK(ga.items[k].label == gb.items[k].label);
          CHECK(ga.items[k].life == gb.items[k].life);
          CHECK(ga.items[k].value == gb.items[k].value);
        }
      }
    }
  }
  CHECK(compared >= 60);  // every intersection test on its primitive's corpus, the mappings on their examples
}

TEST_CASE("rays: stepwise check accepts exact traces and rejects a tampered one", "[rays]") {
  for (const Json& c : read_jsonl("corpus.jsonl"))
    for (const std::string& id : kAlgs.at(c["primitive"])) {
      std::stringstream ss;
      write_trace(find_algorithm(id).open(c["input"], Numeric::exact), ss);
      const CheckReport rep = check_trace(ss);
      INFO(id << " " << c["name"].get<std::string>() << ": " << rep.message);
      CHECK(rep.status == 0);
    }
  std::stringstream ss;
  const Json in = Json::parse(R"({"ray":{"o":[0,0,5],"d":[0,0,-1]},"sphere":{"c":[0,0,0],"r":1}})");
  write_trace(find_algorithm("ray-sphere-stable").open(in, Numeric::exact), ss);
  std::string text = ss.str();
  const auto pos = text.find("\"t\":\"4\"");
  REQUIRE(pos != std::string::npos);
  text.replace(pos, 7, "\"t\":\"5\"");
  std::stringstream bad(text);
  CHECK(check_trace(bad).status == 1);
}
