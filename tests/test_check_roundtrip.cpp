// `check` passes every trace `trace` writes, and any faithful re-serialisation of it: for every
// algorithm, every mode it runs in, its example, its family's corpus and seeded variations of the
// example, the trace re-serialised as Python's json.dumps writes it (", " and ": " separators)
// must pass in the exact modes; a rounded trace may diverge only at a real decision or value, never
// because `check` cannot read its own numbers.
#include <catch2/catch.hpp>
#include <random>
#include <sstream>
#include "catalog.hpp"
#include "corpus.hpp"
#include "scale.hpp"
#include "trace_io.hpp"

using namespace sw;

namespace {

// Json as json.dumps writes it by default: ", " between members and items, ": " after keys.
void spaced(const Json& j, std::string& out) {
  if (j.is_object()) {
    out += '{';
    bool first = true;
    for (auto it = j.begin(); it != j.end(); ++it) {
      out += first ? "" : ", ";
      first = false;
      out += Json(it.key()).dump() + ": ";
      spaced(*it, out);
    }
    out += '}';
  } else if (j.is_array()) {
    out += '[';
    for (std::size_t i = 0; i < j.size(); ++i) {
      out += i ? ", " : "";
      spaced(j[i], out);
    }
    out += ']';
  } else {
    out += j.dump();
  }
}

std::string round_trip(const std::string& trace) {
  std::istringstream in(trace);
  std::string line, out;
  while (std::getline(in, line)) {
    spaced(Json::parse(line), out);
    out += '\n';
  }
  return out;
}

// The example with each number moved a little (a seeded variation; inputs it makes invalid are skipped).
Json vary(Json j, std::mt19937_64& rng) {
  if (j.is_number_integer()) return j.get<std::int64_t>() + std::int64_t(rng() % 3) - 1;
  if (j.is_number_float()) return j.get<double>() * (1 + std::uniform_real_distribution<double>(-0.05, 0.05)(rng));
  if (j.is_structured())
    for (Json& v : j) v = vary(v, rng);
  return j;
}

// Every trace of a family's algorithms, in every mode, passes check also re-serialised; returns how many.
std::size_t round_trip_family(std::string_view family) {
  std::mt19937_64 rng(29);
  std::size_t traces = 0;
  for (const Algorithm& alg : catalog()) {
    if (alg.family != family) continue;
    std::vector<Json> inputs = testing::corpus(alg.family);
    const Json example = Json::parse(alg.example);
    inputs.push_back(example);
    for (int k = 0; k < 6; ++k) inputs.push_back(vary(example, rng));
    std::size_t accepted = 0;  // this algorithm's runs: the sanitizer build checks every 8th
    for (const Json& input : inputs)
      for (Numeric n : alg.numerics) {
        std::optional<Run> run;
        try {
          run.emplace(alg.open(input, n));
          run->check_budget(Budget{20'000});  // long traces add time, not cases
        } catch (const InputError&) {
          continue;  // another algorithm's corpus entry, a variation out of bounds, fractions in int mode
        }
        if (!testing::kept(accepted++)) continue;
        std::stringstream trace;
        write_trace(*run, trace);
        ++traces;
        for (const std::string& text : {trace.str(), round_trip(trace.str())}) {
          std::istringstream in(text);
          const CheckReport rep = check_trace(in);
          INFO(alg.id << " " << numeric_name(n) << " " << input.dump().substr(0, 300) << "\n" << rep.message.substr(0, 600));
          CHECK(rep.status != 2);
          if (n == Numeric::exact || n == Numeric::reference || n == Numeric::integer || n == Numeric::filtered) CHECK(rep.status == 0);
          // A rounded run may take another branch than exact (that is what its trace shows), but
          // check must say so about a step's line, kind, integer or decision, or a number beyond
          // the tolerance: never fail to read a number.
          if (rep.status == 1) CHECK(rep.message.find("is not a number") == std::string::npos);
          if (rep.status == 1) CHECK(rep.message.find("characters") == std::string::npos);
        }
      }
  }
  return traces;
}

}  // namespace

// One test per family, so that ctest runs them side by side.
TEST_CASE("check round trip: lines", "[check][roundtrip]") { CHECK(round_trip_family("lines") > testing::cases(50u)); }
TEST_CASE("check round trip: curves", "[check][roundtrip]") { CHECK(round_trip_family("curves") > testing::cases(50u)); }
TEST_CASE("check round trip: rays", "[check][roundtrip]") { CHECK(round_trip_family("rays") > testing::cases(50u)); }
TEST_CASE("check round trip: fill", "[check][roundtrip]") { CHECK(round_trip_family("fill") > testing::cases(50u)); }
TEST_CASE("check round trip: spatial", "[check][roundtrip]") { CHECK(round_trip_family("spatial") > testing::cases(50u)); }
TEST_CASE("check round trip: lighting", "[check][roundtrip]") { CHECK(round_trip_family("lighting") > testing::cases(50u)); }
TEST_CASE("check round trip: tracer", "[check][roundtrip]") { CHECK(round_trip_family("tracer") >= testing::cases(5u)); }
TEST_CASE("check round trip: pipeline", "[check][roundtrip]") { CHECK(round_trip_family("pipeline") > testing::cases(50u)); }
TEST_CASE("check round trip: shadows", "[check][roundtrip]") { CHECK(round_trip_family("shadows") >= testing::cases(16u)); }
