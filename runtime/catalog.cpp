#include "catalog.hpp"
#include <algorithm>
#include <array>
#include <filesystem>
#include <stdexcept>
#include <tuple>

namespace sw {

namespace {

// The families in the order of the course (and of `stepwise list`, which sorts each family's
// algorithms by id); a family folder not named here sorts after them by name.
constexpr std::array<std::string_view, 9> kFamilyOrder = {"lines", "curves", "rays", "fill", "spatial", "lighting", "tracer", "pipeline", "shadows"};

struct Registration {
  Algorithm (*make)();
  std::string family;
};

std::vector<Registration>& registrations() {
  static std::vector<Registration> all;
  return all;
}

std::size_t family_rank(std::string_view f) {
  return std::size_t(std::find(kFamilyOrder.begin(), kFamilyOrder.end(), f) - kFamilyOrder.begin());
}

}  // namespace

Registrar::Registrar(Algorithm (*make)(), const char* file) {
  registrations().push_back({make, std::filesystem::path(file).parent_path().filename().string()});
}

namespace {
std::vector<std::pair<std::string_view, Listing>>& callees() {
  static std::vector<std::pair<std::string_view, Listing>> all;
  return all;
}
}  // namespace

CalleeRegistrar::CalleeRegistrar(std::string_view id, Listing listing) { callees().emplace_back(id, listing); }

const Listing* find_listing(std::string_view id) {
  for (const Algorithm& a : catalog())
    if (a.id == id) return &a.listing;
  for (const auto& [callee, listing] : callees())
    if (callee == id) return &listing;
  return nullptr;
}

std::vector<std::string_view> listing_ids() {
  std::vector<std::string_view> ids;
  for (const Algorithm& a : catalog()) ids.push_back(a.id);
  for (const auto& c : callees()) ids.push_back(c.first);
  return ids;
}

const std::vector<Algorithm>& catalog() {
  static const std::vector<Algorithm> all = [] {
    // The entries' family views point into registrations(), which is never changed again.
    std::vector<Algorithm> v;
    for (const Registration& r : registrations()) {
      v.push_back(r.make());
      v.back().family = r.family;
    }
    std::sort(v.begin(), v.end(), [](const Algorithm& a, const Algorithm& b) {
      return std::tuple(family_rank(a.family), a.family, a.id) < std::tuple(family_rank(b.family), b.family, b.id);
    });
    for (std::size_t k = 0; k + 1 < v.size(); ++k)
      if (v[k].id == v[k + 1].id) throw std::logic_error("two algorithms registered as " + std::string(v[k].id));
    return v;
  }();
  return all;
}

bool Algorithm::supports(Numeric n) const { return std::find(numerics.begin(), numerics.end(), n) != numerics.end(); }

bool Algorithm::declares_result(std::string_view key) const {
  return std::find(result_keys.begin(), result_keys.end(), key) != result_keys.end();
}

std::string Algorithm::modes_text() const {
  std::string modes;
  for (Numeric n : numerics) modes += (modes.empty() ? "" : ", ") + std::string(numeric_name(n));
  return modes;
}

void sort_result_set(Json& result, std::string_view key) {
  Json& set = result[std::string(key)];
  std::sort(set.begin(), set.end());
}

Numeric Algorithm::replay_mode() const {
  for (Numeric n : {Numeric::exact, Numeric::reference, Numeric::f64})
    if (supports(n)) return n;
  return numerics.front();
}

Run Algorithm::open(const Json& input, Numeric n) const {
  if (!supports(n)) throw InputError(std::string(id) + " does not run on '" + std::string(numeric_name(n)) + "' (it runs on: " + modes_text() + ")");
  return Run(fn.open(*this, input), n);
}

std::vector<Run> Algorithm::seeded_runs(std::size_t per_set, Numeric n) const {
  std::vector<Run> runs;
  for (auto& in : fn.seeded(*this, per_set)) runs.emplace_back(std::move(in), n);
  return runs;
}

const Algorithm* algorithm_by_id(std::string_view id) {
  for (const Algorithm& a : catalog())
    if (a.id == id) return &a;
  return nullptr;
}

const Algorithm& find_algorithm(std::string_view id) {
  if (const Algorithm* a = algorithm_by_id(id)) return *a;
  std::string known;
  for (const Algorithm& a : catalog()) known += (known.empty() ? "" : ", ") + std::string(a.id);
  throw InputError("unknown algorithm '" + one_line(id, 60) + "' (known: " + known + ")");
}

Numeric parse_numeric_for(const Algorithm& alg, std::string_view name) {
  auto n = parse_numeric(name);
  if (!n) throw InputError("unknown numeric mode '" + one_line(name, 60) + "' (known: float, double, int, filtered, exact, reference)");
  if (!alg.supports(*n))
    throw InputError(std::string(alg.id) + " does not run on '" + std::string(name) + "' (it runs on: " + alg.modes_text() + ")");
  return *n;
}

std::string catalog_markdown() {
  std::string out = "| family | id | what | modes |\n|---|---|---|---|\n";
  for (const Algorithm& a : catalog())
    out += "| " + std::string(a.family) + " | `" + std::string(a.id) + "` | " + std::string(a.summary) + " | " + a.modes_text() + " |\n";
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
