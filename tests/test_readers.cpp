// The readers' promises (docs/cli.md): duplicate keys found in linear time and named, unknown keys
// refused by every algorithm, and files named inside data (a mesh, a scene) that are not regular
// files refused at once rather than read (a FIFO would hang the reader).
#include <catch2/catch.hpp>
#include <sys/stat.h>
#include <unistd.h>
#include <filesystem>
#include "catalog.hpp"
#include "cli_harness.hpp"

using namespace sw;
using namespace sw::testing;

TEST_CASE("readers: 320,000 keys are read in linear time, and a duplicate among them is named", "[readers][reliability]") {
  // Quadratic duplicate detection took more than 300 s on this input; the test's own time limit
  // (ctest's 120 s) is the bound.
  constexpr int kKeys = 320000;
  std::string text = "{";
  for (int k = 0; k < kKeys; ++k) text += (k ? ",\"k" : "\"k") + std::to_string(k) + "\":" + std::to_string(k);
  const Json ok = parse_json_text(text + "}", "input");
  CHECK(ok.size() == std::size_t(kKeys));
  CHECK_THROWS_WITH(parse_json_text(text + ",\"k123456\":0}", "input"), Catch::Contains("duplicate key \"k123456\""));
  // Nested objects are checked each on their own: the same key at two levels is no duplicate.
  CHECK_NOTHROW(parse_json_text(R"({"a":{"a":1},"b":{"a":2}})", "input"));
  CHECK_THROWS_WITH(parse_json_text(R"({"a":{"x":1,"y":2,"x":3}})", "input"), Catch::Contains("duplicate key \"x\""));
}

TEST_CASE("readers: every algorithm refuses an unknown key in its input", "[readers][catalog]") {
  for (const Algorithm& a : catalog()) {
    INFO(a.id);
    Json in = Json::parse(a.example);
    in["zz_unknown"] = 1;
    CHECK_THROWS_WITH(a.open(in), Catch::Contains("zz_unknown"));
  }
}

TEST_CASE("readers: a FIFO or a device named as a mesh or a scene is refused, not read", "[readers][reliability]") {
  const auto dir = scratch("readers-fifo");
  const auto fifo = dir / "mesh.off";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const Json ray = {{"o", {0, 0, 5}}, {"d", {0, 0, -1}}};
  for (const char* id : {"bvh-traverse", "kd-traverse", "ray-triangles"}) {
    INFO(id);
    CHECK_THROWS_WITH(find_algorithm(id).open({{"mesh", fifo.string()}, {"ray", ray}}), Catch::Contains("is not a regular file"));
  }
  CHECK_THROWS_WITH(find_algorithm("octree-build").open({{"mesh", "/dev/zero.off"}}), Catch::Contains("mesh"));
  const auto scene = dir / "scene.json";
  REQUIRE(::mkfifo(scene.c_str(), 0600) == 0);
  CHECK_THROWS_WITH(find_algorithm("whitted").open({{"scene", scene.string()}, {"pixel", {0, 0}}}), Catch::Contains("is not a regular file"));
  // The CLI: one line, exit 2, and it returns (the ctest time limit catches a hang).
  const auto r = run_stepwise("trace bvh-traverse --input " + sh_quote(Json{{"mesh", fifo.string()}, {"ray", ray}}.dump()));
  CHECK(r.status == 2);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}
