// Tests for blind spots the mutation run found (scripts/mutate.sh, tests/mutants.txt): each names
// the planted bug it catches that no other test did.
#include <catch2/catch.hpp>
#include <cstdint>
#include <set>
#include <sstream>
#include <string>
#include <vector>
#include "catalog.hpp"
#ifdef SW_HAVE_VISUALIZER
#include "headless/headless.hpp"
#endif

using namespace sw;

namespace {

// One recorded number against the same number in a JSONL line: exact modes write "p/q" strings
// (the lossless text), rounded modes JSON numbers (the double itself).
void same_number(const TraceView& t, std::uint32_t slot, const Json& j) {
  if (j.is_string()) CHECK(j.get<std::string>() == t.num_text(slot));
  else CHECK(j.get<double>() == t.num_double(slot));
}

}  // namespace

// jsonl-vec2-swap: `check` replays through the JSONL writer on both sides, and the step
// expectations read the Recorder, so a writer that swaps a vector's components (or drops a label)
// passed everything. The two probes must write the same steps.
TEST_CASE("trace formats: the JSONL stream and the Recorder agree on every step of every example", "[catalog][probe]") {
  for (const Algorithm& alg : catalog()) {
    for (Numeric n : alg.numerics) {
      INFO(alg.id << " " << numeric_name(n));
      const Json input = Json::parse(alg.example);
      try {
        (void)alg.open(input, n);
      } catch (const InputError&) {
        continue;  // e.g. int mode and a fractional example
      }
      const Recorded rec = alg.open(input, n).record();
      const TraceView& t = *rec.trace;
      std::ostringstream out;
      alg.open(input, n).stream(out);
      std::istringstream lines(out.str());
      std::string line;
      std::size_t s = 0;
      while (std::getline(lines, line)) {
        const Json j = Json::parse(line);
        if (j.contains("result")) {
          CHECK(j["result"] == rec.result);
          break;
        }
        REQUIRE(s < t.size());
        const StepRecord& st = t.at(s);
        INFO("step " << s);
        CHECK(j.at("step") == s);
        CHECK(j.at("line") == st.line);
        CHECK(j.at("kind") == std::string(kind_name(st.kind)));
        CHECK(j.contains("in") == (st.scope != 0));
        if (st.scope) CHECK(j["in"] == std::string(t.scope_id(st.scope)));
        // Variables by name (JSON objects do not keep their order), component by component.
        const Json& vars = j.at("vars");
        std::set<std::string> names;
        for (std::uint32_t v = st.var_begin; v < st.var_end; ++v) {
          const VarRecord& var = t.var_at(v);
          INFO("variable " << var.name);
          names.insert(var.name);
          REQUIRE(vars.contains(var.name));
          const auto it = vars.find(var.name);
          if (var.is_int && var.shape == VarShape::list) {
            REQUIRE(it->size() == var.count);
            for (std::uint32_t c = 0; c < var.count; ++c) CHECK((*it)[c].get<std::int64_t>() == t.int_value(var.slot + c));
          } else if (var.is_int) {
            CHECK(it->get<std::int64_t>() == t.int_value(var.slot));
          } else if (var.shape == VarShape::colour) {
            REQUIRE(it->contains("rgb"));
            for (std::uint32_t c = 0; c < 3; ++c) same_number(t, var.slot + c, (*it)["rgb"][c]);
          } else if (var.count == 1) {
            same_number(t, var.slot, *it);
          } else {
            REQUIRE(it->size() == var.count);
            for (std::uint32_t c = 0; c < var.count; ++c) same_number(t, var.slot + c, (*it)[c]);
          }
        }
        CHECK(vars.size() == names.size());
        // Geometry items in order: the kind and its values, then the label, lifetime and value.
        const Json& geo = j.at("geo");
        REQUIRE(geo.size() == st.geo_end - st.geo_begin);
        for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g) {
          const GeoRecord& r = t.geo_at(g);
          const Json& item = geo[g - st.geo_begin];
          const std::string kind(geo_name(r.kind));
          INFO("geometry item " << g - st.geo_begin << " " << kind);
          REQUIRE(item.contains(kind));
          REQUIRE(item[kind].size() == r.count);
          for (std::uint32_t k = 0; k < r.count; ++k) {
            if (geo_desc(r.kind).integer) CHECK(item[kind][k].get<std::int64_t>() == t.int_value(r.slot + k));
            else same_number(t, r.slot + k, item[kind][k]);
          }
          CHECK(item.contains("label") == (r.label != nullptr));
          if (r.label) CHECK(item["label"] == std::string(r.label));
          CHECK(item.contains("life") == (r.life != Life::step));
          if (r.life != Life::step) CHECK(item["life"] == std::string(life_name(r.life)));
          CHECK(item.contains("value") == (r.value != GeoRecord::kNoValue));
          if (r.value != GeoRecord::kNoValue) same_number(t, r.value, item["value"]);
        }
        ++s;
      }
      CHECK(s == t.size());
    }
  }
}

#ifdef SW_HAVE_VISUALIZER
// canvas-y-up: the render tests find cells through the canvas's own cell_rect, so a canvas that
// drew world y downward (image and cell_rect alike) passed them. World y goes up the screen.
TEST_CASE("pixel canvas: world x goes right and world y goes up the screen", "[visualizer][render]") {
  vis::HeadlessHost host(960, 600);
  vis::App& app = host.app();
  REQUIRE(app.session().open_algorithm(find_algorithm("dda-line"), parse_json_text(R"({"p0":[1.25,2.5],"p1":[12.75,7.25]})", "t"),
                             Numeric::exact));
  host.render();
  const vis::Canvas* c = app.canvas(0);
  REQUIRE(c);
  const auto a = c->cell_rect({5, 4}), right = c->cell_rect({6, 4}), up = c->cell_rect({5, 5});
  REQUIRE(a);
  REQUIRE(right);
  REQUIRE(up);
  // Rects are (left, top, right, bottom) in screen pixels, y down.
  CHECK((*a)[0] < (*a)[2]);
  CHECK((*a)[1] < (*a)[3]);
  CHECK((*right)[0] > (*a)[0]);
  CHECK((*up)[1] < (*a)[1]);
}
#endif
