// `check`'s fast path (check_fast.cpp) against the full comparison it stands in for: on every
// algorithm's example, each step of each rounded trace, and that step tampered with in the ways a
// wrong trace differs, step_agrees may say "agrees" only where require_step_shape and step_diff find
// nothing; and it must say so for the untampered steps, or the fast path is never taken.
#include <catch2/catch.hpp>
#include <sstream>
#include "catalog.hpp"
#include "check_step.hpp"
#include "trace_io.hpp"

using namespace sw;
using namespace sw::check_values;

namespace {

std::vector<std::string> lines_of(const Algorithm& alg, Numeric n) {
  std::stringstream s;
  write_trace(alg.open(Json::parse(alg.example), n), s);
  std::vector<std::string> out;
  std::string line;
  while (std::getline(s, line)) out.push_back(line);
  return out;
}

// The full path's verdict: nothing found.
bool full_agrees(const std::string& want, const std::string& got, std::size_t index, const Tolerance& tol) {
  try {
    const Json w = Json::parse(want), g = parse_json_text(got, "line");
    if (g.contains("result")) return false;
    require_step_shape(g, 1, true);
    if (g.contains("step") && g["step"] != Json(index)) return false;
    return !step_diff(w, g, tol, Listing{});
  } catch (const InputError&) {
    return false;
  }
}

// A step's line tampered with: the first number scaled, an integer moved, a field dropped or added.
std::vector<std::string> tampered(const std::string& line) {
  Json j = Json::parse(line);
  std::vector<std::string> out;
  auto with = [&](auto edit) {
    Json t = j;
    edit(t);
    out.push_back(t.dump());
  };
  for (auto it = j["vars"].begin(); it != j["vars"].end(); ++it) {
    const std::string key = it.key();
    if (it->is_number_integer()) with([&](Json& t) { t["vars"][key] = t["vars"][key].get<std::int64_t>() + 1; });
    if (it->is_number_float()) {
      with([&](Json& t) { t["vars"][key] = t["vars"][key].get<double>() * (1 + 1e-6) + 1e-9; });
      with([&](Json& t) { t["vars"][key] = t["vars"][key].get<double>() * (1 + 1e-13); });
    }
    with([&](Json& t) { t["vars"].erase(key); });
  }
  with([&](Json& t) { t["vars"]["extra"] = 1; });
  with([&](Json& t) { t["kind"] = "tampered"; });
  with([&](Json& t) { t["line"] = t["line"].get<std::int64_t>() + 1; });
  with([&](Json& t) { t["step"] = t["step"].get<std::int64_t>() + 1; });
  with([&](Json& t) { t["in"] = "other"; });
  with([&](Json& t) { t["geo"].push_back(Json{{"pixel", {0, 0}}}); });
  if (!j["geo"].empty()) {
    with([&](Json& t) { t["geo"].erase(0); });
    with([&](Json& t) { t["geo"][0]["label"] = "tampered"; });
    with([&](Json& t) { t["geo"][0]["life"] = "forever"; });
  }
  out.push_back(line + " {}");
  out.push_back(line.substr(0, line.size() - 1));
  return out;
}

}  // namespace

TEST_CASE("check fast path: agrees only where the full comparison agrees, on every algorithm", "[check]") {
  std::size_t fast = 0, compared = 0;
  FlatJson w, g;
  for (const Algorithm& alg : catalog()) {
    if (!alg.supports(Numeric::exact)) continue;
    const std::vector<std::string> exact = lines_of(alg, Numeric::exact);
    for (Numeric n : alg.numerics) {
      if (n == Numeric::exact || n == Numeric::integer || n == Numeric::reference) continue;
      const std::vector<std::string> rounded = lines_of(alg, n);
      const Tolerance tol{mode_tolerance(n)};
      // Steps only: the header and the result line are not steps.
      for (std::size_t i = 1; i + 1 < std::min(exact.size(), rounded.size()) && i < 400; ++i) {
        if (rounded[i].find("\"result\"") == 0 || exact[i].starts_with("{\"result\"")) break;
        std::vector<std::string> cases = tampered(rounded[i]);
        cases.push_back(rounded[i]);
        for (const std::string& got : cases) {
          const bool quick = w.read(exact[i]) && g.read(got) && step_agrees(w, g, i - 1, tol, true);
          INFO(alg.id << " " << numeric_name(n) << " step " << i - 1 << ": " << got);
          if (quick) CHECK(full_agrees(exact[i], got, i - 1, tol));
          fast += quick;
          ++compared;
        }
      }
    }
  }
  INFO(fast << " of " << compared << " lines agreed on the fast path");
  CHECK(fast > compared / 20);  // the untampered steps and the harmless tampering (1e-13) take it
}
