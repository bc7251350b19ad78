// Tests that iterate the whole catalog by family: every listing line is reached by some step, the
// README's algorithm table is `stepwise list --markdown`, and every declaration is well formed.
#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <sstream>
#include <set>
#include "catalog.hpp"
#include "cli_harness.hpp"
#include "corpus.hpp"
#include "trace_io.hpp"

using namespace sw;

namespace {

// A loop header ("while ...:", "for ...:", "repeat ...:") has no step of its own: its test shows on
// the steps inside the loop. Recognised by the code ending in ':' (before any "--" comment).
bool loop_header(std::string_view text) {
  text = text.substr(0, text.find("--"));
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return !text.empty() && text.back() == ':';
}

// Other lines with no step of their own, each with the reason: their values are recorded by the
// step of the line named.
const std::map<std::pair<std::string_view, std::string_view>, std::string_view> kUnreached = {
    {{"dda-grid-walk", "up"}, "recorded by visit_up"},
    {{"dda-grid-walk", "down"}, "recorded by visit_down"},
    {{"ray-box", "slab"}, "recorded by clip"},
    {{"ray-box", "order"}, "recorded by clip"},
    {{"ray-sphere-geometric", "hit"}, "recorded by root (a hit step)"},
    {{"ray-triangle-barycentric", "edges"}, "recorded by normal"},
    {{"ray-triangle-mt", "pvec"}, "recorded by det"},
    {{"ray-triangle-mt", "inv"}, "recorded by u"},
    {{"ray-triangle-mt", "tvec"}, "recorded by u"},
    {{"ray-triangle-mt", "qvec"}, "recorded by v"},
    {{"ray-triangle-watertight", "retry"}, "float only, and only when an edge function is 0"},
};

}  // namespace

// Also: the work budget's estimate (docs/cli.md) is an upper bound on the steps of these runs.
TEST_CASE("catalog: every listing line is reached by a step of the examples and the corpus, within the step estimate", "[catalog][budget]") {
  for (const Algorithm& alg : catalog()) {
    INFO(alg.id);
    const Numeric n = alg.supports(Numeric::exact) ? Numeric::exact : Numeric::f64;
    std::set<std::uint32_t> reached;
    std::vector<Json> inputs = testing::corpus(alg.family);
    inputs.push_back(Json::parse(alg.example));
    std::size_t ran = 0;
    for (const Json& in : inputs) {
      std::optional<Run> run;
      try {
        run.emplace(alg.open(in, n));
      } catch (const InputError&) {
        continue;  // another algorithm's input in the family corpus
      }
      const Recorded rec = run->record();
      ++ran;
      if (const auto estimate = run->estimate_steps()) CHECK(rec.trace->size() <= *estimate);
      std::set<std::uint8_t> scopes;
      for (std::size_t s = 0; s < rec.trace->size(); ++s) {
        if (rec.trace->at(s).scope == 0) reached.insert(rec.trace->at(s).line);  // nested steps are the callee's lines
        else scopes.insert(rec.trace->at(s).scope);
      }
      // Every callee a trace steps into has its listing by its id (`list --listing`, check's messages).
      for (std::uint8_t k : scopes) {
        INFO("callee " << rec.trace->scope_id(k));
        const Listing* l = find_listing(rec.trace->scope_id(k));
        REQUIRE(l);
        CHECK(l->title == rec.trace->scope_listing(k).title);
        CHECK(l->lines.size() == rec.trace->scope_listing(k).lines.size());
      }
    }
    CHECK(ran > 0);
    for (Numeric m : alg.numerics) {  // rounded modes may take other paths
      std::optional<Run> run;
      try {
        run.emplace(alg.open(Json::parse(alg.example), m));
      } catch (const InputError&) {
        continue;  // an example the int mode does not take (fractions)
      }
      if (const auto estimate = run->estimate_steps()) CHECK(run->record().trace->size() <= *estimate);
    }
    for (std::uint32_t id = 1; id <= alg.listing.lines.size(); ++id) {
      const std::string_view name = alg.listing.lines[id - 1].name;
      INFO("line " << id << " (" << name << ")");
      if (kUnreached.count({alg.id, name})) CHECK(!reached.count(id));  // keep the allow-list honest
      else if (!loop_header(alg.listing.lines[id - 1].text)) CHECK(reached.count(id));
    }
  }
}

TEST_CASE("catalog: declarations are well formed", "[catalog]") {
  std::set<std::string_view> ids;
  for (const Algorithm& alg : catalog()) {
    INFO(alg.id);
    CHECK(ids.insert(alg.id).second);
    CHECK(!alg.views.empty());
    CHECK(!alg.numerics.empty());
    std::set<std::string_view> names;
    for (const ListingLine& l : alg.listing.lines) CHECK(names.insert(l.name).second);
    CHECK_NOTHROW((void)alg.open(Json::parse(alg.example), alg.numerics.front()));
  }
}

TEST_CASE("catalog: the README's algorithm table is stepwise list --markdown", "[catalog][cli]") {
  const auto r = testing::run_stepwise("list --markdown");
  REQUIRE(r.status == 0);
  CHECK(r.out == catalog_markdown());
  const std::string readme = testing::slurp(std::filesystem::path(SW_SOURCE_DIR) / "README.md");
  CHECK_THAT(readme, Catch::Contains(r.out));
}

TEST_CASE("catalog: check accepts every algorithm's own exact, reference and int traces and reads every mode's", "[catalog][check]") {
  for (const Algorithm& alg : catalog()) {
    for (Numeric n : alg.numerics) {
      INFO(alg.id << " " << numeric_name(n));
      std::stringstream trace;
      try {
        (void)alg.open(Json::parse(alg.example), n);
      } catch (const InputError&) {
        continue;  // the example is not this mode's input (fractions in int mode)
      }
      write_trace(alg.open(Json::parse(alg.example), n), trace);
      const CheckReport rep = check_trace(trace);
      INFO(rep.message);
      if (n == Numeric::exact || n == Numeric::reference || n == Numeric::integer) CHECK(rep.status == 0);
      else CHECK(rep.status != 2);  // rounded modes may diverge, but their traces are always readable
    }
  }
}

TEST_CASE("catalog: docs/trace.schema.json is the schema derived from the vocabulary", "[catalog][cli]") {
  const auto r = testing::run_stepwise("schema");
  REQUIRE(r.status == 0);
  CHECK(r.out == trace_schema());
  CHECK(testing::slurp(std::filesystem::path(SW_SOURCE_DIR) / "docs" / "trace.schema.json") == r.out);
  // Every geometry kind is in it, with its arity.
  const Json schema = Json::parse(r.out);
  const Json& props = schema["$defs"]["step"]["properties"]["geo"]["items"]["properties"];
  for (const GeoDesc& g : kGeoDescs) {
    INFO(g.name);
    REQUIRE(props.contains(std::string(g.name)));
    if (g.arity) CHECK(props[std::string(g.name)]["maxItems"] == g.arity);
  }
}

TEST_CASE("catalog: every Catch2 test name survives ctest's registration", "[catalog][suite]") {
  // ctest splits a registered name at ';' and trims it; such a test would match no case and run
  // nothing (this found one in the ray tests). Names must also be unique (a duplicate is
  // registered once). Commas are escaped by Catch's ctest registration and are fine.
  std::set<std::string> names;
  for (const Catch::TestCase& tc : Catch::getAllTestCasesSorted(*Catch::getCurrentContext().getConfig())) {
    const std::string& name = tc.getTestCaseInfo().name;
    INFO(name);
    CHECK(name.find(';') == std::string::npos);
    CHECK(!name.empty());
    CHECK(name.front() != ' ');
    CHECK(name.back() != ' ');
    CHECK(names.insert(name).second);
  }
  CHECK(names.size() > 50);
}
