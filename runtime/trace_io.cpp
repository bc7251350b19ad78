// Trace files (docs/trace-format.md): the schema and header, writing traces atomically, batches.
#include "trace_io.hpp"
#include <unistd.h>
#include <algorithm>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <random>

namespace sw {

namespace {

// The temporaries being written, for the signal handler: fixed storage, no allocation there.
constexpr int kMaxTemps = 8;
char g_temps[kMaxTemps][4096];
volatile std::sig_atomic_t g_temp_used[kMaxTemps];

extern "C" void remove_temps_and_die(int sig) {
  for (int k = 0; k < kMaxTemps; ++k)
    if (g_temp_used[k]) ::unlink(g_temps[k]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

int register_temp(const std::string& path) {
  static const bool installed = [] {
    std::signal(SIGINT, remove_temps_and_die);
    std::signal(SIGTERM, remove_temps_and_die);
    return true;
  }();
  (void)installed;
  if (path.size() >= sizeof g_temps[0]) return -1;
  for (int k = 0; k < kMaxTemps; ++k)
    if (!g_temp_used[k]) {
      std::memcpy(g_temps[k], path.c_str(), path.size() + 1);
      g_temp_used[k] = 1;
      return k;
    }
  return -1;
}

void unregister_temp(const std::string& path) {
  for (int k = 0; k < kMaxTemps; ++k)
    if (g_temp_used[k] && path == g_temps[k]) g_temp_used[k] = 0;
}

// A symbolic link's final target (a chain of links, each relative to its own directory); bounded.
std::filesystem::path follow_links(std::filesystem::path p) {
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(p, ec))) return p;
    const std::filesystem::path to = std::filesystem::read_symlink(p, ec);
    if (ec) throw InputError("cannot read the link " + p.string());
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  throw InputError("--out " + p.string() + ": too many levels of symbolic links");
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(follow_links(std::move(target))) {
  std::error_code ec;
  const auto st = std::filesystem::status(target_, ec);
  using std::filesystem::file_type;
  if (st.type() == file_type::fifo || st.type() == file_type::character) {  // written through
    out_.open(target_, std::ios::binary);
    if (!out_) throw InputError("cannot write " + target_.string());
    return;
  }
  if (st.type() == file_type::directory) throw InputError("--out " + target_.string() + " is a directory");
  if (st.type() != file_type::not_found && st.type() != file_type::regular)
    throw InputError("--out " + target_.string() + " is neither a file, a FIFO nor a character device");
  std::random_device rd;
  temp_ = target_;
  temp_ += ".tmp-" + std::to_string(rd());
  register_temp(temp_.string());
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    unregister_temp(temp_.string());
    throw InputError("cannot write " + target_.string());
  }
}

AtomicFile::~AtomicFile() {
  if (committed_ || temp_.empty()) return;
  out_.close();
  std::error_code ec;
  std::filesystem::remove(temp_, ec);
  unregister_temp(temp_.string());
}

void AtomicFile::commit() {
  out_.close();
  if (!out_) throw InputError("cannot write " + target_.string());
  if (!temp_.empty()) {
    std::filesystem::rename(temp_, target_);
    unregister_temp(temp_.string());
  }
  committed_ = true;
}

namespace {
// The longest string in an input: exact numbers are strings ("p/q", decimals), at most 4096
// characters each (input.cpp). Depth is bounded by the JSON readers (kMaxJsonDepth).
std::size_t longest_string(const Json& j) {
  if (j.is_string()) return j.get_ref<const std::string&>().size();
  std::size_t m = 0;
  if (j.is_structured())
    for (const Json& v : j) m = std::max(m, longest_string(v));
  return m;
}
}  // namespace

std::uint64_t step_weight(const Json& input, Numeric n) {
  if (n != Numeric::exact && n != Numeric::filtered) return 1;  // rounded modes convert the input once
  return 1 + longest_string(input) / kDigitsPerWeight;
}

void check_budget(const Algorithm& alg, const Json& input, Numeric n, const Budget& budget) {
  if (!alg.estimate_steps) return;  // constant step counts, or bounded when parsed (docs/cli.md)
  const std::uint64_t steps = alg.estimate_steps(input, n), cost = alg.step_cost ? alg.step_cost(n) : 1, weight = step_weight(input, n);
  auto times = [](std::uint64_t a, std::uint64_t b) -> std::uint64_t {  // saturating
    return b != 0 && a > UINT64_MAX / b ? UINT64_MAX : a * b;
  };
  const std::uint64_t total = times(times(steps, cost), weight);
  if (total > budget.max_steps) {
    std::string why;
    if (cost > 1) why += " x " + std::to_string(cost) + " for " + std::string(alg.id) + "'s steps in " + std::string(numeric_name(n));
    if (weight > 1) why += " x " + std::to_string(weight) + " for exact numbers of " + std::to_string(longest_string(input)) + " characters";
    throw InputError("this input implies up to " + std::to_string(steps) + " steps" + why + ", more than the budget of " +
                     std::to_string(budget.max_steps) + " (--max-steps raises it)");
  }
}

BudgetedStream::BudgetedStream(std::ostream& out, std::uint64_t max) : std::ostream(&buf_) {
  buf_.out = &out, buf_.max = max;
  exceptions(std::ios::badbit);  // the budget's InputError passes through
}

void BudgetedStream::Buf::count(std::streamsize n) {
  written += std::uint64_t(n);
  if (written > max) throw InputError("the output passes the budget of " + std::to_string(max) + " bytes (--max-output raises it)");
}

BudgetedStream::Buf::int_type BudgetedStream::Buf::overflow(int_type c) {
  if (c == traits_type::eof()) return c;
  count(1);
  out->put(char(c));
  return c;
}

std::streamsize BudgetedStream::Buf::xsputn(const char* s, std::streamsize n) {
  count(n);
  out->write(s, n);
  return n;
}

std::string trace_schema() {
  using OJ = nlohmann::ordered_json;
  const OJ number = {{"$ref", "#/$defs/number"}};
  OJ kinds = OJ::array(), numerics = OJ::array(), geo_props = OJ::object(), lives = OJ::array();
  for (std::string_view k : kStepKindNames) kinds.push_back(k);
  for (std::string_view l : kLifeNames) lives.push_back(l);
  for (Numeric n : kNumerics) numerics.push_back(numeric_name(n));
  for (const GeoDesc& g : kGeoDescs) {
    OJ item = {{"type", "array"}, {"items", g.integer ? OJ{{"type", "integer"}} : number}};
    if (g.arity) item["minItems"] = g.arity, item["maxItems"] = g.arity;
    else item["minItems"] = g.dim, item["description"] = "a list of " + std::to_string(g.dim) + "D points, coordinates in order";
    geo_props[std::string(g.name)] = std::move(item);
  }
  OJ geo_item = {{"type", "object"},
                 {"description", "One kind key with its values, and optionally a label, a lifetime and a value (a colour key)."},
                 {"minProperties", 1},
                 {"maxProperties", 4},
                 {"properties", geo_props},
                 {"additionalProperties", false}};
  geo_item["properties"]["label"] = {{"type", "string"}};
  geo_item["properties"]["life"] = {{"enum", lives}, {"description", "step: this step only; keep: from now on; replace: from now on, replacing the earlier item with this label"}};
  geo_item["properties"]["value"] = number;
  OJ s;
  s["$schema"] = "https://json-schema.org/draft/2020-12/schema";
  s["$id"] = "stepwise-trace-v2";
  s["title"] = "One line of a stepwise trace (JSONL, version 2; check also reads version 1)";
  s["description"] = "Line 1 is a header, the last line a result, every line between a step. See docs/trace-format.md. Generated by `stepwise schema`.";
  s["oneOf"] = OJ::array({{{"$ref", "#/$defs/header"}}, {{"$ref", "#/$defs/step"}}, {{"$ref", "#/$defs/result"}}});
  OJ defs;
  defs["number"] = {{"description", "A JSON number (its exact double value) or an exact rational string."},
                    {"oneOf", OJ::array({{{"type", "number"}}, {{"type", "string"}, {"pattern", "^[-+]?[0-9]+(/[0-9]+|\\.[0-9]+)?$"}}})}};
  defs["header"] = {{"type", "object"},
                    {"required", OJ::array({"format", "version", "algorithm", "numeric", "input"})},
                    {"properties",
                     {{"format", {{"const", "stepwise-trace"}}},
                      {"version", {{"enum", OJ::array({1, 2})}}},
                      {"algorithm", {{"type", "string"}}},
                      {"numeric", {{"enum", numerics}}},
                      {"input", {{"type", "object"}}},
                      {"tolerance", number},
                      {"listing", {{"type", "array"}, {"items", {{"type", "string"}}}}}}}};
  defs["step"] = {{"type", "object"},
                  {"required", OJ::array({"step", "line", "kind", "vars", "geo"})},
                  {"properties",
                   {{"step", {{"type", "integer"}, {"minimum", 0}}},
                    {"in", {{"type", "string"}, {"description", "inside a nested call: the callee's id; line is in its listing"}}},
                    {"line", {{"type", "integer"}, {"minimum", 1}}},
                    {"kind", {{"enum", kinds}}},
                    {"vars", {{"type", "object"},
                              {"description", "A number, a list of numbers (a vector of 2 or 3, or a short list such as a traversal stack), or a colour."},
                              {"additionalProperties",
                               {{"oneOf", OJ::array({number,
                                                     {{"type", "array"}, {"items", number}, {"maxItems", kMaxListLength}},
                                                     {{"type", "object"},
                                                      {"required", OJ::array({"rgb"})},
                                                      {"additionalProperties", false},
                                                      {"properties", {{"rgb", {{"type", "array"}, {"items", number}, {"minItems", 3}, {"maxItems", 3}}}}}}})}}}}},
                    {"geo", {{"type", "array"}, {"items", geo_item}}}}}};
  defs["result"] = {{"type", "object"}, {"required", OJ::array({"result"})}, {"properties", {{"result", {{"type", "object"}}}}}, {"additionalProperties", false}};
  s["$defs"] = std::move(defs);
  return s.dump(2) + "\n";
}

std::string trace_header(const Algorithm& alg, Numeric n, const Json& input) {
  nlohmann::ordered_json h;  // keeps the documented key order
  h["format"] = "stepwise-trace";
  h["version"] = 2;
  h["algorithm"] = alg.id;
  h["numeric"] = numeric_name(n);
  h["input"] = nlohmann::ordered_json::parse(input.dump());
  // How closely `check` holds this trace's numbers to the replay's (0: exactly).
  h["tolerance"] = mode_tolerance(n).get_str();
  nlohmann::ordered_json names = nlohmann::ordered_json::array();
  for (const ListingLine& l : alg.listing.lines) names.push_back(l.name);
  h["listing"] = std::move(names);  // step "line" k is listing[k - 1]
  return h.dump();
}

void write_trace(const Algorithm& alg, Numeric n, const Json& input, std::ostream& out) {
  alg.validate(input, n);
  out << trace_header(alg, n, input) << '\n';
  alg.stream(input, n, out);
}

std::size_t run_batch(const Algorithm& alg, Numeric n, std::istream& in, std::ostream& out, const Budget& budget) {
  std::vector<Json> inputs;
  std::string line;
  for (std::size_t k = 1; read_line(in, line, kMaxJsonBytes, "line " + std::to_string(k)); ++k) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      Json j = parse_json_text(line, "input");
      alg.validate(j, n);
      check_budget(alg, j, n, budget);
      inputs.push_back(std::move(j));
    } catch (const InputError& e) {
      throw InputError("line " + std::to_string(k) + ": " + e.what());
    }
  }
  for (const Json& j : inputs) alg.run_to(j, n, out);
  return inputs.size();
}

// Exact and int traces are exact; float, double and filtered traces are rounded by design;
// reference traces carry the 300-bit functions' rounding.
Rational mode_tolerance(Numeric n) {
  auto pow2 = [](int e) { return Rational(1, mpz_class(1) << e); };
  switch (n) {
    case Numeric::f32: return pow2(10);
    case Numeric::f64:
    case Numeric::filtered: return pow2(36);
    case Numeric::reference: return pow2(200);
    case Numeric::integer:
    case Numeric::exact: return 0;
  }
  return 0;
}

}  // namespace sw
