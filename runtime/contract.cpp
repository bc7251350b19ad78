// `stepwise list --contract ALG`: the trace contract, collected from traced sample runs.
#include "contract.hpp"
#include <algorithm>
#include <map>
#include "trace_io.hpp"

namespace sw {

namespace {

// Sample runs: the example, the contract inputs, and up to this many inputs of each seeded set,
// while the steps traced stay within kContractMaxSteps.
constexpr std::size_t kSeededPerSet = 16;

std::string var_type(const VarRecord& v, const std::string& number) {
  const std::string t = v.is_int ? "integer" : number;
  switch (v.shape) {
    case VarShape::scalar: return t;
    case VarShape::vector: return v.count == 3 ? "[" + t + ", " + t + ", " + t + "]" : "[" + t + ", " + t + "]";
    case VarShape::colour: return "{\"rgb\": [" + t + ", " + t + ", " + t + "]}";
    case VarShape::list: return "[" + t + ", ...]";
  }
  return t;
}

// A JSON value's type, for the header's input and the result: numbers as the replay writes them.
std::string json_type(const Json& v, const std::string& number, std::size_t depth = 0) {
  if (depth > 8) return "...";
  if (v.is_boolean()) return "boolean";
  if (v.is_number_integer()) return "integer";
  if (v.is_number()) return number;
  if (v.is_string()) {
    try {
      (void)parse_rational(v, "", kMaxExactTextChars);
      return number;
    } catch (const InputError&) {
      return "string";
    }
  }
  if (v.is_array()) {
    if (v.empty()) return "[]";
    const bool scalars = std::all_of(v.begin(), v.end(), [](const Json& x) { return !x.is_structured(); });
    if (scalars && v.size() <= 3) {  // a point or a pixel: its entries one by one
      std::string t = "[";
      for (std::size_t i = 0; i < v.size(); ++i) t += (i ? ", " : "") + json_type(v[i], number, depth + 1);
      return t + "]";
    }
    return "[" + json_type(v[0], number, depth + 1) + ", ...]";
  }
  if (v.is_object()) {
    std::string t = "{";
    for (auto it = v.begin(); it != v.end(); ++it) t += (t.size() > 1 ? ", " : "") + it.key() + ": " + json_type(*it, number, depth + 1);
    return t + "}";
  }
  return "null";
}

ContractStep step_form(const TraceView& t, const StepRecord& s, const std::string& number) {
  ContractStep f;
  f.kind = kind_name(s.kind);
  for (std::uint32_t v = s.var_begin; v < s.var_end; ++v) f.vars.emplace_back(t.var_at(v).name, var_type(t.var_at(v), number));
  for (std::uint32_t g = s.geo_begin; g < s.geo_end; ++g) {
    const GeoRecord& r = t.geo_at(g);
    std::string item(geo_name(r.kind));
    if (r.label) item += " \"" + std::string(r.label) + "\"";
    // A run of items of one kind and label (a tree's nodes) is one entry: their number varies.
    if (!f.geo.empty() && (f.geo.back() == item || f.geo.back() == item + " ...")) f.geo.back() = item + " ...";
    else f.geo.push_back(item);
  }
  return f;
}

// "2^-36", or "0".
std::string tolerance_text(Numeric n) {
  const Rational tol = mode_tolerance(n);
  if (tol == 0) return "0";
  return "2^-" + std::to_string(mpz_sizeinbase(tol.get_den().get_mpz_t(), 2) - 1);
}

std::string modes_rule(Numeric n) {
  const Rational tol = mode_tolerance(n);
  if (tol == 0) return "numbers equal the replay's exactly (\"p/q\" strings or JSON numbers)";
  return "|got - e| <= " + tolerance_text(n) + " x (1 + |e|), e the replay's value";
}

std::string replay_text(const Contract& c) {
  const std::string mode(numeric_name(c.replay));
  const bool has_int = c.algorithm->supports(Numeric::integer);
  return mode + (has_int && c.replay != Numeric::integer ? " (an int trace in int)" : "");
}

Contract collect(const Algorithm& alg) {
  Contract c;
  c.algorithm = &alg;
  c.replay = alg.replay_mode();
  c.number_type = c.replay == Numeric::exact || c.replay == Numeric::integer ? "exact" : "real";
  c.example = Json::parse(alg.example);

  std::vector<Run> samples{alg.open(c.example, c.replay)};
  for (std::string_view text : alg.contract_inputs) samples.push_back(alg.open(Json::parse(text), c.replay));
  for (Run& r : alg.seeded_runs(kSeededPerSet, c.replay)) samples.push_back(std::move(r));

  // Forms seen per (listing, line), in order of first sight; callees in order of first call.
  std::map<std::pair<std::string, std::size_t>, std::vector<ContractStep>> seen;
  std::vector<std::pair<std::string, Listing>> callees;
  std::map<std::string, std::size_t> result_seen;  // key -> runs whose result has it
  for (const Run& run : samples) {
    const std::optional<std::uint64_t> units = run.budget_units();
    if (c.runs && (c.steps >= kContractMaxSteps || (units && *units > kContractMaxSteps - c.steps))) continue;  // a long line adds nothing but time
    const Recorded rec = run.record();
    const TraceView& t = *rec.trace;
    ++c.runs;
    c.steps += t.size();
    for (std::size_t i = 0; i < t.size(); ++i) {
      const StepRecord& s = t.at(i);
      std::string in;
      if (s.scope) {
        in = std::string(t.scope_id(s.scope));
        if (std::none_of(callees.begin(), callees.end(), [&](const auto& x) { return x.first == in; })) callees.emplace_back(in, t.scope_listing(s.scope));
      }
      auto& forms = seen[{in, s.line}];
      ContractStep f = step_form(t, s, c.number_type);
      if (std::find(forms.begin(), forms.end(), f) == forms.end()) forms.push_back(std::move(f));
    }
    if (rec.result.is_object())
      for (auto it = rec.result.begin(); it != rec.result.end(); ++it) {
        if (!result_seen.count(it.key())) c.result.emplace_back(it.key(), json_type(*it, c.number_type));
        ++result_seen[it.key()];
      }
  }
  for (auto& [key, type] : c.result)
    if (result_seen[key] < c.runs) type += " (in some results)";

  auto add_listing = [&](const std::string& in, const Listing& l) {
    for (std::size_t k = 0; k < l.lines.size(); ++k) {
      ContractLine line{in, k + 1, std::string(l.lines[k].name), std::string(l.lines[k].text), {}};
      if (auto it = seen.find({in, k + 1}); it != seen.end()) line.steps = it->second;
      c.lines.push_back(std::move(line));
    }
  };
  add_listing("", alg.listing);
  for (const auto& [in, l] : callees) add_listing(in, l);
  return c;
}

// A callee that is an algorithm of its own (dda-line inside bezier-forward-diff, phong inside
// whitted) records the same steps inside a call as alone: its own sample runs add the forms the
// caller's runs did not reach.
void add_callee_forms(Contract& c) {
  std::vector<std::string> done;
  for (const ContractLine& l : c.lines) {
    if (l.in.empty() || l.in == c.algorithm->id || std::find(done.begin(), done.end(), l.in) != done.end()) continue;
    done.push_back(l.in);
    const Algorithm* callee = algorithm_by_id(l.in);
    if (!callee) continue;  // a callee with no input of its own (refract)
    const Contract own = collect(*callee);
    for (ContractLine& line : c.lines) {
      if (line.in != l.in) continue;
      for (const ContractLine& o : own.lines)
        if (o.in.empty() && o.line == line.line)
          for (const ContractStep& f : o.steps)
            if (std::find(line.steps.begin(), line.steps.end(), f) == line.steps.end()) line.steps.push_back(f);
    }
  }
}

}  // namespace

Contract make_contract(const Algorithm& alg) {
  Contract c = collect(alg);
  add_callee_forms(c);
  return c;
}

std::string contract_text(const Contract& c) {
  const Algorithm& alg = *c.algorithm;
  std::string out;
  auto put = [&](const std::string& s) { out += s + "\n"; };
  put(std::string(alg.id) + ": the trace contract of `stepwise check " + std::string(alg.id) + "` traces (docs/trace-format.md)");
  put("Generated from the listing and " + std::to_string(c.runs) + " traced runs in " + std::string(numeric_name(c.replay)) +
      " (the example, the contract inputs and seeded inputs; " + std::to_string(c.steps) + " steps).");
  put("");
  put("Header (line 1):");
  put("  {\"format\":\"stepwise-trace\",\"version\":2,\"algorithm\":\"" + std::string(alg.id) + "\",\"numeric\":MODE,\"input\":INPUT}");
  put("  MODE: " + alg.modes_text());
  put("  INPUT: " + json_type(c.example, "number") + "  (numbers: JSON numbers or exact \"p/q\" strings)");
  put("  example: " + c.example.dump());
  put("");
  put("Steps (one line each, in order; \"step\" counts from 0):");
  put("  {\"step\":N,\"line\":LINE,\"kind\":KIND,\"vars\":{NAME:VALUE,...},\"geo\":[ITEM,...]}");
  put("  A step inside a callee adds \"in\":\"CALLEE\"; its LINE is in the callee's listing.");
  put("  Types: integer: a JSON integer in every mode; " + c.number_type +
      ": a number of the trace's mode (exact: a \"p/q\" string; float, double: a JSON number); [a, b]: a vector.");
  put("  Geometry: {\"pixel\":[i,j]}, {\"point\":[x,y]}, ... (docs/trace-format.md); a label in quotes is optional.");
  std::string scope = "-";
  for (const ContractLine& l : c.lines) {
    if (l.in != scope) {
      scope = l.in;
      put("");
      put(l.in.empty() ? "Listing " + std::string(alg.listing.title) + " (line: name: text, then each form of step recorded there):"
                       : "Inside " + l.in + " (steps with \"in\":\"" + l.in + "\"; lines of " + l.in + "'s listing):");
    }
    put((l.line < 10 ? "   " : "  ") + std::to_string(l.line) + " " + l.name + ": " + listing_text(l.text));
    if (l.steps.empty()) put("       (no step on this line in the sample runs)");
    for (const ContractStep& f : l.steps) {
      std::string row = "       " + f.kind + "  vars {";
      for (std::size_t k = 0; k < f.vars.size(); ++k) row += (k ? ", " : "") + f.vars[k].first + ": " + f.vars[k].second;
      row += "}  geo [";
      for (std::size_t k = 0; k < f.geo.size(); ++k) row += (k ? ", " : "") + f.geo[k];
      put(row + "]");
    }
  }
  put("");
  put("Result (last line): {\"result\":{...}}");
  for (const auto& [key, type] : c.result) put("  " + key + ": " + type);
  if (alg.supports(Numeric::filtered)) put("  (filtered traces add \"fallback\": true|false, which is not compared)");
  put("");
  put("How check compares (it replays the input in " + replay_text(c) + "):");
  put("  line, kind, \"in\", the variables' names, the geometry items' number and kinds: equal, step by step");
  put("  integer variables and pixel/span items: equal, in every mode");
  put("  other numbers (variables, geometry), by the trace's MODE:");
  for (Numeric n : alg.numerics) {
    std::string mode(numeric_name(n));
    mode.resize(std::max<std::size_t>(mode.size(), 9), ' ');
    put("    " + mode + " tolerance " + tolerance_text(n) + ": " + modes_rule(n));
  }
  put("  a geometry item's label, life and value: compared only where the trace states them");
  put("  the result: against the independent oracle by the same rules" +
      std::string(alg.supports(Numeric::reference) ? " (a reference trace's numbers within 2^-52: both sides rounded once)" : ""));
  put("  --decisions-only: numbers are not compared and a step may leave out \"geo\"");
  put("  --results-only: the result alone; the steps are read past");
  return out;
}

std::string contract_json(const Contract& c) {
  const Algorithm& alg = *c.algorithm;
  using OJson = nlohmann::ordered_json;
  OJson j;
  j["algorithm"] = alg.id;
  j["replay"] = numeric_name(c.replay);
  j["runs"] = c.runs;
  j["steps"] = c.steps;
  OJson modes = OJson::array();
  for (Numeric n : alg.numerics) modes.push_back(numeric_name(n));
  j["header"] = {{"format", "stepwise-trace"}, {"version", 2}, {"algorithm", alg.id}, {"numeric", modes}, {"input", OJson::parse(c.example.dump())}};
  OJson lines = OJson::array();
  for (const ContractLine& l : c.lines) {
    OJson line;
    if (!l.in.empty()) line["in"] = l.in;
    line["line"] = l.line;
    line["name"] = l.name;
    line["text"] = l.text;
    OJson steps = OJson::array();
    for (const ContractStep& f : l.steps) {
      OJson vars = OJson::object();
      for (const auto& [name, type] : f.vars) vars[name] = type;
      steps.push_back({{"kind", f.kind}, {"vars", vars}, {"geo", f.geo}});
    }
    line["steps"] = steps;
    lines.push_back(line);
  }
  j["lines"] = lines;
  OJson result = OJson::object();
  for (const auto& [key, type] : c.result) result[key] = type;
  j["result"] = result;
  OJson tol = OJson::object();
  for (Numeric n : alg.numerics) tol[std::string(numeric_name(n))] = tolerance_text(n);
  j["tolerance"] = tol;
  return j.dump();
}

}  // namespace sw
