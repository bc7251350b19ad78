#include "trace_io.hpp"
#include <functional>
#include <random>
#include <sstream>

namespace sw {

AtomicFile::AtomicFile(std::filesystem::path target) : target_(std::move(target)) {
  std::random_device rd;
  temp_ = target_;
  temp_ += ".tmp-" + std::to_string(rd());
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) throw InputError("cannot write " + target_.string());
}

AtomicFile::~AtomicFile() {
  if (committed_) return;
  out_.close();
  std::error_code ec;
  std::filesystem::remove(temp_, ec);
}

void AtomicFile::commit() {
  out_.close();
  if (!out_) throw InputError("cannot write " + target_.string());
  std::filesystem::rename(temp_, target_);
  committed_ = true;
}

std::string trace_header(const Algorithm& alg, Numeric n, const Json& input) {
  nlohmann::ordered_json h;  // keeps the documented key order
  h["format"] = "stepwise-trace";
  h["version"] = 1;
  h["algorithm"] = alg.id;
  h["numeric"] = numeric_name(n);
  h["input"] = nlohmann::ordered_json::parse(input.dump());
  return h.dump();
}

void write_trace(const Algorithm& alg, Numeric n, const Json& input, std::ostream& out) {
  alg.validate(input, n);
  out << trace_header(alg, n, input) << '\n';
  alg.stream(input, n, out);
}

std::size_t run_batch(const Algorithm& alg, Numeric n, std::istream& in, std::ostream& out) {
  std::vector<Json> inputs;
  std::string line;
  for (std::size_t k = 1; std::getline(in, line); ++k) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      Json j = parse_json_text(line, "input");
      alg.validate(j, n);
      inputs.push_back(std::move(j));
    } catch (const InputError& e) {
      throw InputError("line " + std::to_string(k) + ": " + e.what());
    }
  }
  for (const Json& j : inputs) out << alg.run(j, n).dump() << '\n';
  return inputs.size();
}

namespace {

struct Divergence {
  std::string what;
};

// A JSON value read as an exact rational (numbers exactly as the double they are).
Rational as_rational(const Json& v, const std::string& what) { return parse_rational(v, what); }

// Structural equality where numbers compare as exact rationals. "fallback" is informational.
bool same_value(const Json& a, const Json& b) {
  const bool na = a.is_number() || a.is_string(), nb = b.is_number() || b.is_string();
  if (na && nb) {
    try {
      return as_rational(a, "") == as_rational(b, "");
    } catch (const InputError&) {
      return a == b;
    }
  }
  if (a.is_array() && b.is_array()) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!same_value(a[i], b[i])) return false;
    return true;
  }
  if (a.is_object() && b.is_object()) {
    for (auto it = a.begin(); it != a.end(); ++it)
      if (it.key() != "fallback" && (!b.contains(it.key()) || !same_value(*it, b[it.key()]))) return false;
    for (auto it = b.begin(); it != b.end(); ++it)
      if (it.key() != "fallback" && !a.contains(it.key())) return false;
    return true;
  }
  return a == b;
}

// Calls back once per line written to it: `check` watches the exact run's JSONL as it is made.
class LineSink : public std::streambuf {
 public:
  explicit LineSink(std::function<void(const std::string&)> on_line) : on_line_(std::move(on_line)) {}

 protected:
  int_type overflow(int_type c) override {
    if (c != traits_type::eof()) put(static_cast<char>(c));
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    for (std::streamsize i = 0; i < n; ++i) put(s[i]);
    return n;
  }

 private:
  void put(char c) {
    if (c != '\n') return line_.push_back(c);
    on_line_(line_);
    line_.clear();
  }
  std::function<void(const std::string&)> on_line_;
  std::string line_;
};

// Thrown through the exact run to stop it at the first divergence.
struct Diverged {
  std::string message;
};

// Does the trace's step agree with the reference step?
bool step_agrees(const Json& want, const Json& got, bool decisions_only) {
  if (got.at("line") != want.at("line") || got.at("kind") != want.at("kind")) return false;
  const Json& wv = want.at("vars");
  const Json& gv = got.at("vars");
  if (wv.size() != gv.size()) return false;
  for (auto it = wv.begin(); it != wv.end(); ++it) {
    if (!gv.contains(it.key())) return false;
    const bool is_int = it->is_number_integer();
    if (decisions_only && !is_int) continue;
    if (!same_value(*it, gv[it.key()])) return false;
  }
  const Json& wg = want.at("geo");
  const Json& gg = got.at("geo");
  if (wg.size() != gg.size()) return false;
  for (std::size_t k = 0; k < wg.size(); ++k) {
    const auto first = wg[k].begin();  // each geometry item is a one-key object
    const std::string name = first.key();
    const Json& values = first.value();
    if (!gg[k].is_object() || gg[k].size() != 1 || !gg[k].contains(name)) return false;
    const auto kind = parse_geo(name);
    if (!kind) return false;
    if (decisions_only && !geo_desc(*kind).decision) continue;  // the vocabulary's rule
    if (!same_value(values, gg[k][name])) return false;
  }
  return true;
}

void require_step_shape(const Json& j, std::size_t lineno) {
  auto bad = [&](const char* why) { throw InputError("line " + std::to_string(lineno) + ": " + why); };
  if (!j.is_object()) bad("expected a step object");
  if (!j.contains("line") || !j["line"].is_number_integer()) bad("step without an integer \"line\"");
  if (!j.contains("kind") || !j["kind"].is_string()) bad("step without a string \"kind\"");
  if (!j.contains("vars") || !j["vars"].is_object()) bad("step without a \"vars\" object");
  if (!j.contains("geo") || !j["geo"].is_array()) bad("step without a \"geo\" array");
  for (auto it = j["vars"].begin(); it != j["vars"].end(); ++it)
    if (!it->is_number() && !it->is_string()) bad("a variable that is neither a number nor a \"p/q\" string");
    else if (it->is_string()) (void)parse_rational(*it, "line " + std::to_string(lineno) + ": vars." + it.key());
}

}  // namespace

CheckReport check_trace(std::istream& in, bool decisions_only) {
  CheckReport rep;
  std::string line;
  std::size_t lineno = 0;
  // The next non-blank line's text (in `line`), or false at the end.
  auto next_text = [&]() -> bool {
    while (std::getline(in, line)) {
      ++lineno;
      if (line.find_first_not_of(" \t\r") != std::string::npos) return true;
    }
    return false;
  };
  auto next_line = [&]() -> std::optional<Json> {
    if (!next_text()) return std::nullopt;
    return parse_json_text(line, "line " + std::to_string(lineno));
  };
  auto is_result = [](const Json& j) { return j.is_object() && j.contains("result"); };
  try {
    auto header = next_line();
    if (!header) throw InputError("empty trace");
    if (!header->is_object() || header->value("format", "") != "stepwise-trace")
      throw InputError("line 1: not a stepwise trace header (\"format\":\"stepwise-trace\")");
    if (header->value("version", 0) != 1) throw InputError("line 1: unsupported version (expected 1)");
    const Algorithm& alg = find_algorithm(require(*header, "algorithm", "line 1").get<std::string>());
    const Json& numeric = require(*header, "numeric", "line 1");
    if (!numeric.is_string()) throw InputError("line 1: \"numeric\" must be a string");
    parse_numeric_for(alg, numeric.get<std::string>());
    const Json input = require(*header, "input", "line 1");
    if (!alg.supports(Numeric::exact))
      throw InputError("check replays in exact mode, and " + std::string(alg.id) + " has none");
    alg.validate(input, Numeric::exact);

    // Replay: the exact run streams its steps; each is compared with the trace's next line as it
    // is made, so memory stays flat however long the trace.
    std::size_t i = 0;
    std::optional<Json> pending;  // a trace line read but not yet matched
    LineSink sink([&](const std::string& text) {
      if (text.rfind("{\"result\"", 0) == 0) return;  // the oracle judges the result
      if (!next_text()) throw InputError("no result line ({\"result\":...}) at the end of the trace");
      if (line == text) {  // byte-identical (our own exact traces): agrees without parsing
        ++i;
        return;
      }
      const Json want = Json::parse(text);
      pending = parse_json_text(line, "line " + std::to_string(lineno));
      if (is_result(*pending))
        throw Diverged{"step " + std::to_string(i) + " diverges: expected " + want.dump() + " got the end of the steps"};
      require_step_shape(*pending, lineno);
      if (!step_agrees(want, *pending, decisions_only))
        throw Diverged{"step " + std::to_string(i) + " diverges: expected " + want.dump() + " got " + pending->dump()};
      pending.reset();
      ++i;
    });
    std::ostream replay(&sink);
    replay.exceptions(std::ios::badbit);  // let Diverged and InputError through the stream
    alg.stream(input, Numeric::exact, replay);

    auto last = next_line();
    if (last && !is_result(*last)) {
      require_step_shape(*last, lineno);
      throw Diverged{"step " + std::to_string(i) + " diverges: expected the end of the steps, got " + last->dump()};
    }
    if (!last) throw InputError("no result line ({\"result\":...}) at the end of the trace");
    if (next_line()) throw InputError("line " + std::to_string(lineno) + ": content after the result line");
    const Json oracle = alg.oracle(input);
    if (!same_value(alg.canonical(oracle), alg.canonical((*last)["result"])))
      throw Diverged{"result diverges: expected " + oracle.dump() + " got " + (*last)["result"].dump()};
    rep.steps = i;
    rep.message = "ok: " + std::to_string(i) + " steps and the result agree with the exact oracle";
  } catch (const Diverged& d) {
    rep.status = 1;
    rep.message = d.message;
  } catch (const InputError& e) {
    rep.status = 2;
    rep.message = e.what();
  } catch (const Json::exception& e) {
    rep.status = 2;
    rep.message = std::string("malformed trace: ") + e.what();
  }
  return rep;
}

}  // namespace sw
