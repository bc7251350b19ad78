// `stepwise check`: replays a trace in exact (or reference) mode and compares it step by step and
// field by field, then its result with the oracle. Format and rules: docs/trace-format.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>
#include "check_result.hpp"
#include "check_step.hpp"
#include "check_values.hpp"
#include "trace_io.hpp"

namespace sw {

namespace {

using check_values::canonical;
using check_values::Held;
using check_values::read_result;
using check_values::read_trace_line;
using check_values::result_diff;
using check_values::Tolerance;
using check_values::line_label;
using check_values::require_step_shape;
using check_values::show;
using check_values::step_context;
using check_values::step_agrees;
using check_values::step_diff;

// Nesting depth of a JSON value, without recursion (check_values::kMaxNesting bounds it).
using check_values::kMaxNesting;
// A trace line is JSON text, read only up to the JSON readers' bound.
constexpr std::size_t kMaxTraceLine = kMaxJsonBytes;
std::size_t nesting(const Json& root) {
  std::vector<std::pair<const Json*, std::size_t>> todo{{&root, 1}};
  std::size_t deepest = 0;
  while (!todo.empty()) {
    const auto [j, d] = todo.back();
    todo.pop_back();
    deepest = std::max(deepest, d);
    if (d > kMaxNesting) return d;
    if (j->is_structured())
      for (const Json& c : *j) todo.push_back({&c, d + 1});
  }
  return deepest;
}

// Calls back once per step line written to it: `check` watches the exact run's JSONL as it is
// made. The result line, which the oracle judges, is passed over and not kept.
class LineSink : public std::streambuf {
 public:
  explicit LineSink(std::function<void(const std::string&)> on_line) : on_line_(std::move(on_line)) {}

 protected:
  int_type overflow(int_type c) override {
    if (c != traits_type::eof()) {
      const char ch = static_cast<char>(c);
      xsputn(&ch, 1);
    }
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    for (const char* end = s + n; s != end;) {
      const char* eol = static_cast<const char*>(std::memchr(s, '\n', static_cast<std::size_t>(end - s)));
      if (!result_) {
        line_.append(s, eol ? eol : end);
        result_ = line_.starts_with("{\"result\"");
      }
      if (!eol) break;
      if (!result_) on_line_(line_);
      line_.clear();
      result_ = false;
      s = eol + 1;
    }
    return n;
  }

 private:
  std::function<void(const std::string&)> on_line_;
  std::string line_;
  bool result_ = false;  // the line is the result line
};

// Thrown through the exact run to stop it at the first divergence.
struct Diverged {
  std::string message, context;
};

}  // namespace

CheckReport check_trace(std::istream& in, CheckScope scope, const Budget& budget) {
  CheckReport rep;
  std::string line;
  std::size_t lineno = 0;
  // The next non-blank line's text (in `line`), or false at the end.
  auto next_text = [&]() -> bool {
    while (read_line(in, line, kMaxTraceLine, "line " + std::to_string(lineno + 1))) {
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
  // Takes a reference: copying a deeply nested value would recurse.
  auto bounded = [&](const Json& j) {
    if (nesting(j) > kMaxNesting) throw InputError("line " + std::to_string(lineno) + ": nested more than " + std::to_string(kMaxNesting) + " levels deep");
  };
  try {
    auto header = next_line();
    if (!header) throw InputError("empty trace");
    bounded(*header);
    if (!header->is_object() || header->value("format", "") != "stepwise-trace")
      throw InputError("line 1: not a stepwise trace header (\"format\":\"stepwise-trace\")");
    const Json version = header->value("version", Json());
    if (version != 1 && version != 2) throw InputError("line 1: unsupported version (expected 1 or 2)");
    const Algorithm& alg = find_algorithm(require(*header, "algorithm", "line 1").get<std::string>());
    const Json& numeric = require(*header, "numeric", "line 1");
    if (!numeric.is_string()) throw InputError("line 1: \"numeric\" must be a string");
    const Numeric mode = parse_numeric_for(alg, numeric.get<std::string>());
    const Json input = require(*header, "input", "line 1");
    // The replay: exact where the algorithm has it, else the reference (transcendental values). An
    // int trace replays in int: integer arithmetic is exact, and a fixed-point algorithm records its
    // values in its own units (triangle-edge: 1/256 pixel).
    // An algorithm with neither (the ray tracer, double only) replays in double: the trace's
    // decisions are held exactly and its numbers within double's tolerance of that replay.
    Numeric replay_mode = mode == Numeric::integer ? Numeric::integer : alg.supports(Numeric::exact) ? Numeric::exact : Numeric::reference;
    if (!alg.supports(replay_mode) && mode != Numeric::integer && alg.supports(Numeric::f64)) replay_mode = Numeric::f64;
    if (!alg.supports(replay_mode)) throw InputError("check replays in exact or reference mode, and " + std::string(alg.id) + " has neither");
    // Exact mode may refuse an input that the rounded modes take (a camera whose frame needs
    // irrational square roots, docs/pipeline/semantics.md); the reference replays it then.
    std::optional<Run> opened;
    try {
      opened.emplace(alg.open(input, replay_mode));
    } catch (const InputError&) {
      if (replay_mode != Numeric::exact || !alg.supports(Numeric::reference)) throw;
      replay_mode = Numeric::reference;
      opened.emplace(alg.open(input, replay_mode));
    }
    const Run& run = *opened;
    run.check_budget(budget);
    const Tolerance tol{mode_tolerance(mode), scope == CheckScope::everything};
    const bool geometry_required = scope == CheckScope::everything;
    const bool rounded = tol.rel > 0 && mode != Numeric::reference;
    // The last step the replay and the trace agree on, as each wrote it (their step i - 1).
    std::string agreed_want, agreed_got;
    std::size_t i = 0;
    // "step 12 diverges at line 9 (advance: q <- q + dp) (trace line 14): variable x: ..."
    auto diverged = [&](const std::string& where, const std::string& what, const std::string& at = "") {
      std::string m = where + " diverges" + (at.empty() ? "" : " at " + at) + " (trace line " + std::to_string(lineno) + "): " + what;
      if (rounded && what.find("beyond the tolerance") != std::string::npos)
        m += "; only values differ: --decisions-only compares the decisions alone";
      return Diverged{m, agreed_want.empty() ? "" : step_context(agreed_want, agreed_got, i - 1, alg.listing, tol)};
    };

    // Replay: the reference run streams its steps; each is compared with the trace's next line as
    // it is made, so memory does not grow with the number of steps. The result line costs memory
    // in its size: its text, and its lists of tuples (pixels) held flat (check_result.hpp).
    std::optional<Json> pending;  // a trace line read but not yet matched
    FlatJson flat_want, flat_got;  // the fast path's readings, reused from step to step
    LineSink sink([&](const std::string& text) {
      if (scope == CheckScope::result) return;  // the trace's steps are read past below
      if (!next_text()) throw InputError("no result line ({\"result\":...}) at the end of the trace");
      if (line == text) {  // byte-identical (our own exact traces): agrees without parsing
        agreed_want = text, agreed_got = line;
        ++i;
        return;
      }
      if (flat_want.read(text) && flat_got.read(line) && step_agrees(flat_want, flat_got, i, tol, geometry_required)) {
        agreed_want = text, agreed_got = line;
        ++i;
        return;
      }
      const Json want = Json::parse(text);
      pending = parse_json_text(line, "line " + std::to_string(lineno));
      bounded(*pending);
      const std::string where = "step " + std::to_string(i);
      auto at = [&] { return line_label(want, alg.listing); };  // looked up for a message only
      if (is_result(*pending)) throw diverged(where, "the trace ends its steps here; the algorithm has more", at());
      require_step_shape(*pending, lineno, geometry_required);
      if (pending->contains("step") && (*pending)["step"] != Json(i))
        throw diverged(where, "step: expected " + std::to_string(i) + ", got " + show((*pending)["step"]) + " (steps are numbered from 0, in order)", at());
      if (auto d = step_diff(want, *pending, tol, alg.listing)) throw diverged(where, *d, at());
      pending.reset();
      agreed_want = text, agreed_got = line;
      ++i;
    });
    std::ostream replay(&sink);
    replay.exceptions(std::ios::badbit);  // let Diverged and InputError through the stream
    run.stream(replay);

    // The lines after the replay's steps: the result line and nothing after it. Results are held
    // with their lists of tuples (pixels) flat (check_result.hpp).
    auto next_held = [&]() -> std::optional<Held> {
      if (!next_text()) return std::nullopt;
      Held l = read_trace_line(line, "line " + std::to_string(lineno));
      bounded(l.json);
      return l;
    };
    auto last = next_held();
    while (scope == CheckScope::result && last && !is_result(last->json)) last = next_held();  // --results-only: steps are not read
    if (last && !is_result(last->json)) {
      require_step_shape(last->json, lineno, geometry_required);
      throw diverged("step " + std::to_string(i), "the algorithm ends its steps here; the trace has more");
    }
    if (!last) throw InputError("no result line ({\"result\":...}) at the end of the trace");
    const std::string result_text = std::move(line), result_what = "line " + std::to_string(lineno);
    if (next_line()) throw InputError("line " + std::to_string(lineno) + ": content after the result line");
    auto result_of = [](Held l) { return Held{std::move(l.json["result"]), std::move(l.lists)}; };
    std::ostringstream oracle;
    run.oracle_to(oracle);
    const Held want = canonical(alg, read_result(std::move(oracle).str()));
    // A reference run's result holds doubles rounded from its 300-bit values, and the oracle's from
    // 400 bits: one rounding each, so they are held within 2^-52 (docs/trace-format.md).
    Tolerance result_tol = tol;
    if (mode == Numeric::reference) result_tol.rel = std::max(tol.rel, Rational(1, mpz_class(1) << 52)), result_tol.rel_d = result_tol.rel.get_d();
    auto d = result_diff(want, canonical(alg, result_of(std::move(*last))), result_tol, false);
    // A rounded result can differ from the oracle's canonical form only because its rounding leaves
    // a shape the canonical form reduces otherwise (a clipped vertex 10^-16 off its edge). It is
    // right when it matches the exact replay's own result within the tolerance, and the replay the
    // oracle. The replay's result is made again for this (not kept: it is rarely needed), and the
    // trace's read again as written.
    if (d && rounded && replay_mode == Numeric::exact) {
      std::ostringstream replay;
      run.run_to(replay);
      const std::string exact_text = std::move(replay).str();
      const Held exact = read_result(exact_text);
      const Held got = result_of(read_trace_line(result_text, result_what));
      if (!result_diff(want, canonical(alg, read_result(exact_text)), Tolerance{Rational(0)}, true) && !result_diff(exact, got, result_tol, false)) d.reset();
    }
    if (d) throw diverged("result", *d);
    rep.steps = i;
    const std::string judge = replay_mode == Numeric::reference ? "reference" : replay_mode == Numeric::f64 ? "double replay and its oracle" : "exact oracle";
    if (scope == CheckScope::result) rep.message = "ok: the result agrees with the " + judge + " (steps not compared: --results-only)";
    else
      rep.message = "ok: " + std::to_string(i) + " steps and the result agree with the " + judge +
                    (scope == CheckScope::decisions ? " (decisions only: lines, kinds and integers)"
                     : tol.rel > 0                 ? " (numbers within " + show(Json(tol.rel.get_str())) + " x (1 + |expected|))"
                                                   : "");
  } catch (const Diverged& d) {
    rep.status = 1;
    rep.message = d.message;
    rep.context = d.context;
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
