// Bad input to the reflection models: one-line InputError naming the problem, for the catalog's
// validate (every numeric mode), and through the CLI: exit 2, one line on stderr, no trace file.
#include <catch2/catch.hpp>
#include "catalog.hpp"
#include "cli_harness.hpp"

using namespace sw;

namespace {

struct Bad {
  const char* id;
  const char* input;
  const char* says;
};

const std::vector<Bad> kBad = {
    {"lambert", R"({"n":[0,0,0],"l":[1,0,1],"e":[0,1,2]})", "input.n: zero-length direction"},
    {"phong", R"({"n":[0,0,1],"l":[0,0,0],"e":[0,1,2],"shininess":2})", "input.l: zero-length direction"},
    {"blinn-phong", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,0,0],"shininess":2})", "input.e: zero-length direction"},
    {"phong", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"shininess":-1})", "input.shininess: -1 is outside [0, 1000000]"},
    {"blinn-phong", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"shininess":-0.5})", "input.shininess: -1/2 is outside"},
    {"oren-nayar", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"sigma":1.5})", "input.sigma: 3/2 is outside [0, 1]"},
    {"oren-nayar", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"sigma":-0.1})", "input.sigma"},
    {"minnaert", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"k":2})", "input.k: 2 is outside [0, 1]"},
    {"toon", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"diffuse":"minnaert","k":-1,"cutoff":0.5})", "input.k"},
    {"gaussian", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"m":0})", "input.m: 0 is outside (0, 100]"},
    {"beckmann", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"m":-0.3})", "input.m"},
    {"cook-torrance", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"m":0,"ior":1.5,"fresnel":"exact"})", "input.m"},
    {"cook-torrance", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"m":0.3,"ior":0.5,"fresnel":"exact"})", "input.ior: 1/2 is outside [1, 100]"},
    {"cook-torrance", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"m":0.3,"ior":1.5,"fresnel":"fast"})", "unknown Fresnel term 'fast'"},
    {"toon", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"diffuse":"phong","cutoff":0.5})", "unknown diffuse model 'phong'"},
    {"toon", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"diffuse":"lambert","cutoff":2})", "input.cutoff: 2 is outside [0, 1]"},
    {"lambert", R"({"n":["nan",0,1],"l":[1,0,1],"e":[0,1,2]})", "input.n[0]: not a finite number"},
    {"lambert", R"({"n":[0,0,1],"l":["inf",0,1],"e":[0,1,2]})", "input.l[0]: not a finite number"},
    {"lambert", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,1e999]})", "overflow"},
    {"lambert", R"({"n":[0,1],"l":[1,0,1],"e":[0,1,2]})", "input.n: expected an array of 3 numbers"},
    {"lambert", R"({"n":[0,0,1],"l":[1,0,1,1],"e":[0,1,2]})", "input.l: expected an array of 3 numbers"},
    {"lambert", R"({"n":[0,0,1],"l":[1,0,1]})", "missing field \"e\""},
    {"lambert", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"k":0.5})", "unknown field \"k\""},
    {"minnaert", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2]})", "missing field \"k\""},
    {"lambert", R"({"n":[0,0,1e16],"l":[1,0,1],"e":[0,1,2]})", "beyond the bound"},
    {"phong", R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"shininess":"abc"})", "input.shininess"},
};

}  // namespace

TEST_CASE("lighting: bad model input is a one-line InputError in every mode", "[lighting][errors]") {
  for (const Bad& b : kBad) {
    INFO(b.id << " " << b.input);
    const Algorithm& alg = find_algorithm(b.id);
    if (std::string_view(b.input).find("1e999") != std::string_view::npos) continue;  // the JSON reader's overflow: CLI case below
    for (Numeric n : alg.numerics) {
      std::string what;
      try {
        (void)alg.open(parse_json_text(b.input, "input"), n);
      } catch (const InputError& e) {
        what = e.what();
      }
      CHECK_THAT(what, Catch::Contains(b.says));
      CHECK(what.find('\n') == std::string::npos);
    }
  }
}

TEST_CASE("lighting: bad model input through the CLI is exit 2, one line and no trace file", "[lighting][errors][cli]") {
  for (std::size_t k = 0; k < kBad.size(); k += 3) {  // a third of them (1e999 among them): each run starts a process
    INFO(kBad[k].id << " " << kBad[k].input);
    SW_CHECK_BAD_TRACE(kBad[k].id, "float", kBad[k].input, kBad[k].says);
  }
  SW_CHECK_BAD_TRACE("toon", "reference", kBad[14].input, kBad[14].says);
}
