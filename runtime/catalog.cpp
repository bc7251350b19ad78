#include "catalog.hpp"
#include <algorithm>

namespace sw {

bool Algorithm::supports(Numeric n) const {
  return std::find(numerics.begin(), numerics.end(), n) != numerics.end();
}

const std::vector<Algorithm>& catalog() {
  static const std::vector<Algorithm> all = [] {
    std::vector<Algorithm> v;
    register_lines(v);
    register_curves(v);
    register_rays(v);
    register_fill(v);
    register_spatial(v);
    register_lighting(v);
    register_tracer(v);
    return v;
  }();
  return all;
}

const Algorithm& find_algorithm(std::string_view id) {
  for (const Algorithm& a : catalog())
    if (a.id == id) return a;
  std::string known;
  for (const Algorithm& a : catalog()) known += (known.empty() ? "" : ", ") + std::string(a.id);
  throw InputError("unknown algorithm '" + one_line(id, 60) + "' (known: " + known + ")");
}

Numeric parse_numeric_for(const Algorithm& alg, std::string_view name) {
  std::string modes;
  for (Numeric n : alg.numerics) modes += (modes.empty() ? "" : ", ") + std::string(numeric_name(n));
  auto n = parse_numeric(name);
  if (!n) throw InputError("unknown numeric mode '" + one_line(name, 60) + "' (known: float, double, int, filtered, exact, reference)");
  if (!alg.supports(*n))
    throw InputError(std::string(alg.id) + " does not run on '" + std::string(name) + "' (it runs on: " + modes + ")");
  return *n;
}

std::string catalog_markdown() {
  std::string out = "| family | id | what | modes |\n|---|---|---|---|\n";
  for (const Algorithm& a : catalog()) {
    std::string modes;
    for (Numeric n : a.numerics) modes += (modes.empty() ? "" : ", ") + std::string(numeric_name(n));
    out += "| " + std::string(a.family) + " | `" + std::string(a.id) + "` | " + std::string(a.summary) + " | " + modes + " |\n";
  }
  return out;
}

std::string catalog_jsonl() {
  std::string out;
  for (const Algorithm& a : catalog()) {
    Json modes = Json::array();
    for (Numeric n : a.numerics) modes.push_back(std::string(numeric_name(n)));
    const Json line{{"id", a.id}, {"family", a.family}, {"what", a.summary}, {"modes", modes}, {"example", Json::parse(a.example)}};
    out += line.dump() + "\n";
  }
  return out;
}

}  // namespace sw
