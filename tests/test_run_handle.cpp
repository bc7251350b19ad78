// One door into every algorithm: a front end opens an input once (Algorithm::open) and asks the run
// handle for everything else. These count the parses (and the mesh files read) of what the CLI's
// trace, run and check do, through the same runtime calls the CLI makes.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include "catalog.hpp"
#include "cli_harness.hpp"
#include "spatial/spatial_common.hpp"
#include "trace_io.hpp"

using namespace sw;

namespace {

// A one-triangle mesh in a fresh temporary directory.
std::filesystem::path write_mesh() {
  const auto dir = sw::testing::scratch("run-handle");
  const auto path = dir / "one.off";
  std::ofstream(path) << "OFF\n3 1 0\n0 0 0\n4 0 0\n0 4 0\n3 0 1 2\n";
  return path;
}

struct Counts {
  std::uint64_t inputs = inputs_opened(), meshes = spatial::mesh_files_opened();
  std::uint64_t more_inputs() const { return inputs_opened() - inputs; }
  std::uint64_t more_meshes() const { return spatial::mesh_files_opened() - meshes; }
};

}  // namespace

TEST_CASE("run handle: trace, run and check parse each input once, and a mesh file is read once", "[catalog][run]") {
  const auto mesh = write_mesh();
  const Json with_mesh = {{"mesh", mesh.string()}, {"ray", {{"o", {1, 1, 5}}, {"d", {0, 0, -1}}}}};
  for (const auto& [id, input] : std::vector<std::pair<std::string, Json>>{
           {"dda-line", Json::parse(R"({"p0":[0,0],"p1":[7,3]})")}, {"bvh-traverse", with_mesh}, {"kd-traverse", with_mesh}}) {
    INFO(id);
    const Algorithm& alg = find_algorithm(id);
    // `stepwise trace`: open, the budget, the header and the steps.
    std::stringstream trace;
    {
      const Counts c;
      const Run run = alg.open(input, Numeric::exact);
      run.check_budget(Budget{});
      write_trace(run, trace);
      CHECK(c.more_inputs() == 1);
      CHECK(c.more_meshes() == (input.contains("mesh") ? 1u : 0u));
    }
    // `stepwise check`: the replay and the oracle on one parse.
    {
      const Counts c;
      const CheckReport rep = check_trace(trace);
      INFO(rep.message);
      CHECK(rep.status == 0);
      CHECK(c.more_inputs() == 1);
      CHECK(c.more_meshes() == (input.contains("mesh") ? 1u : 0u));
    }
    // `stepwise run`: each line parsed once, though all are parsed before any runs.
    {
      const Counts c;
      std::stringstream lines(input.dump() + "\n\n" + input.dump() + "\n"), out;
      CHECK(run_batch(alg, Numeric::f64, lines, out) == 2);
      CHECK(c.more_inputs() == 2);
    }
    // Another mode of an opened input shares its parse.
    {
      const Run exact = alg.open(input, Numeric::exact);
      const Counts c;
      (void)exact.in(Numeric::f32).run();
      (void)exact.in(Numeric::filtered).record();
      CHECK(exact.oracle() == exact.in(Numeric::f64).oracle());
      CHECK(c.more_inputs() == 0);
      CHECK(c.more_meshes() == 0);
    }
  }
}

TEST_CASE("run handle: a mode the algorithm or the input cannot take is refused when opened", "[catalog][run]") {
  const Algorithm& dda = find_algorithm("dda-line");
  CHECK_THROWS_WITH(dda.open(Json::parse(dda.example), Numeric::integer), Catch::Contains("does not run on 'int'"));
  const Algorithm& edge = find_algorithm("triangle-edge");
  const Run fractional = edge.open(Json::parse(R"({"triangle":[[0.1,0],[4,0],[0,4]]})"), Numeric::exact);
  CHECK_THROWS_WITH(fractional.in(Numeric::integer), Catch::Contains("1/256"));
  CHECK_NOTHROW(fractional.in(Numeric::f32));
}
