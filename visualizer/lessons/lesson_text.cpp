// Which section a run shows at a step, and its {templates} filled from the recorded values
// (docs/lessons.md). Conditions compare exactly: an exact run's values as rationals, a float run's
// values as the exact rationals of its doubles.
#include <charconv>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include "lessons/lesson.hpp"
#include "lessons/trace_model.hpp"

namespace sw::vis {

std::pair<std::string, std::optional<std::uint32_t>> split_ref(const std::string& ref) {
  if (const auto dot = ref.rfind('.'); dot != std::string::npos && dot + 2 == ref.size()) {
    static constexpr std::string_view kNames = "xyzrgb";
    if (const auto k = kNames.find(ref[dot + 1]); k != std::string_view::npos) return {ref.substr(0, dot), static_cast<std::uint32_t>(k % 3)};
  }
  if (const auto open = ref.find('['); open != std::string::npos && ref.back() == ']') {
    std::uint32_t k = 0;
    for (std::size_t i = open + 1; i + 1 < ref.size(); ++i) {
      if (ref[i] < '0' || ref[i] > '9' || k > 1000) return {ref, std::nullopt};
      k = k * 10 + static_cast<std::uint32_t>(ref[i] - '0');
    }
    return {ref.substr(0, open), k};
  }
  return {ref, std::nullopt};
}

namespace {

bool is_number(const std::string& s) {
  const std::size_t i = !s.empty() && (s[0] == '-' || s[0] == '+') ? 1 : 0;
  return i < s.size() && (std::isdigit(static_cast<unsigned char>(s[i])) || s[i] == '.');
}

struct Resolved {
  const VarRecord* var = nullptr;
  std::uint32_t component = 0;
  bool whole = true;  // no component named
};

std::optional<Resolved> resolve(const std::string& ref, const TraceModel& run, std::size_t step, std::string& problem) {
  const auto [name, component] = split_ref(ref);
  const VarRecord* v = run.latest_var(step, name);
  if (!v) {
    problem = "'" + name + "' is not recorded at or before step " + std::to_string(step) + " of the " + std::string(numeric_name(run.numeric())) + " run";
    return std::nullopt;
  }
  if (component && *component >= v->count) {
    problem = "'" + ref + "': " + name + " has " + std::to_string(v->count) + " component(s)";
    return std::nullopt;
  }
  return Resolved{v, component.value_or(0), !component};
}

std::string decimal(double x, int digits = 6) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

// A template's format: "exact", "dec" (6 significant digits) or a digit count 1..17; 0 if none of these.
int format_digits(const std::string& format) {
  if (format == "dec") return 6;
  if (format.size() > 2 || format.empty() || !std::all_of(format.begin(), format.end(), [](char c) { return c >= '0' && c <= '9'; })) return 0;
  const int n = std::stoi(format);
  return n >= 1 && n <= 17 ? n : 0;
}

// One component as the state panel shows it: exact "p/q ≈ decimal", an integer as it is, a float's shortest digits;
// or rounded to the format's significant digits (an integer stays whole).
std::string component_text(const TraceModel& run, const VarRecord& v, std::uint32_t k, const std::string& format) {
  const TraceView& t = run.trace();
  std::string text = v.is_int ? std::to_string(t.int_value(v.slot + k)) : t.num_text(v.slot + k);
  const double d = t.component_double(v, k);
  // A float's own shortest digits (the trace writes the double it widens to, up to 17 digits).
  if (!v.is_int && run.numeric() == Numeric::f32 && std::isfinite(d) && double(float(d)) == d) {
    char buf[32];
    text.assign(buf, shortest_chars(buf, buf + sizeof buf, float(d)));
  }
  if (const int digits = format_digits(format); digits && !v.is_int) return decimal(d, digits);
  if (format == "exact" || text.find('/') == std::string::npos) return text;
  return text + " \xE2\x89\x88 " + decimal(d);
}

std::optional<Rational> value_of(const std::string& operand, const TraceModel& run, std::size_t step, std::string& problem) {
  if (is_number(operand)) {
    try {
      return parse_rational(Json(operand), "the number '" + operand + "'");
    } catch (const InputError& e) {
      problem = e.what();
      return std::nullopt;
    }
  }
  const auto r = resolve(operand, run, step, problem);
  if (!r) return std::nullopt;
  if (auto x = exact_value(run, *r->var, r->component)) return x;
  problem = "'" + operand + "' is " + run.trace().num_text(r->var->slot + r->component) + " at step " + std::to_string(step);
  return std::nullopt;
}

int rank(const Narration& n) {
  const int key = n.key == Narration::Key::step ? 3 : n.key == Narration::Key::line ? 2 : 1;
  return key * 4 + (n.conditions.empty() ? 0 : 2) + (n.run.empty() ? 0 : 1);
}

const Narration* best(const Lesson& lesson, const TraceModel& run, std::size_t step, bool quiz) {
  const Narration* out = nullptr;
  for (const Narration& n : lesson.sections)
    if (n.quiz.has_value() == quiz && (!out || rank(n) > rank(*out)) && section_matches(n, lesson, run, step)) out = &n;
  return out;
}

}  // namespace

std::optional<Rational> exact_value(const TraceModel& run, const VarRecord& v, std::uint32_t k) {
  const TraceView& t = run.trace();
  if (v.is_int) return Rational(static_cast<long>(t.int_value(v.slot + k)));
  if (run.numeric() == Numeric::exact) return parse_rational(Json(t.num_text(v.slot + k)), v.name);
  const double d = t.component_double(v, k);
  if (!std::isfinite(d)) return std::nullopt;
  return num::to_rational(d);
}

bool section_matches(const Narration& n, const Lesson& lesson, const TraceModel& run, std::size_t step, std::vector<std::string>* problems) {
  if (step >= run.size()) return false;
  const Algorithm& alg = run.algorithm();
  if (n.run.empty() ? &alg != lesson.algorithm
                    : n.run != alg.id && (&alg != lesson.algorithm || n.run != numeric_name(run.numeric())))
    return false;
  const StepRecord& st = run.trace().at(step);
  const bool key = n.key == Narration::Key::step   ? n.step == step
                   : n.key == Narration::Key::line ? st.line == n.line && (n.callee.empty() ? st.scope == 0 : st.scope != 0 && run.trace().scope_id(st.scope) == n.callee)
                   : n.key == Narration::Key::kind ? st.kind == n.kind
                                                   : false;
  if (!key) return false;
  for (const Condition& c : n.conditions) {
    std::string problem;
    const auto a = value_of(c.lhs, run, step, problem);
    const auto b = a ? value_of(c.rhs, run, step, problem) : std::nullopt;
    if (!a || !b) {
      // A variable the run records, but not yet: simply false. Unknown names are the lint's.
      const auto known = [&](const std::string& ref) {
        const auto& names = run.var_names();
        return is_number(ref) || std::find(names.begin(), names.end(), split_ref(ref).first) != names.end();
      };
      if (problems && !(known(c.lhs) && known(c.rhs) && problem.find("is not recorded") != std::string::npos)) problems->push_back("condition '" + c.lhs + " " + c.op + " " + c.rhs + "': " + problem);
      return false;
    }
    const int s = cmp(*a, *b);
    const bool holds = c.op == "<" ? s < 0 : c.op == "<=" ? s <= 0 : c.op == ">" ? s > 0 : c.op == ">=" ? s >= 0 : c.op == "==" ? s == 0 : s != 0;
    if (!holds) return false;
  }
  return true;
}

const Narration* Lesson::section_for(const TraceModel& run, std::size_t step) const { return best(*this, run, step, false); }
const Narration* Lesson::quiz_for(const TraceModel& run, std::size_t step) const { return best(*this, run, step, true); }

Filled fill_templates(const std::string& text, const TraceModel& run, std::size_t step) {
  Filled out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size() && (text[i + 1] == '{' || text[i + 1] == '}')) {
      out.text += text.substr(i, 2);  // Markdown's own escape: the renderer shows the brace
      ++i;
      continue;
    }
    const auto close = text[i] == '{' ? text.find('}', i) : std::string::npos;
    if (close == std::string::npos || close - i > 64) {
      out.text += text[i];
      continue;
    }
    std::string ref = text.substr(i + 1, close - i - 1), format;
    if (const auto colon = ref.find(':'); colon != std::string::npos) format = ref.substr(colon + 1), ref = ref.substr(0, colon);
    i = close;
    if (!format.empty() && format != "exact" && !format_digits(format)) {
      out.problems.push_back("template '{" + ref + ":" + format + "}': the format is exact, dec or a digit count 1 to 17");
      continue;
    }
    if (ref == "step") {
      out.text += std::to_string(step);
      continue;
    }
    if (ref == "numeric") {
      out.text += numeric_name(run.numeric());
      continue;
    }
    std::string problem;
    const auto r = resolve(ref, run, step, problem);
    if (!r) {
      out.problems.push_back("template '{" + ref + "}': " + problem);
      out.text += "{" + ref + "?}";
      continue;
    }
    const VarRecord& v = *r->var;
    if (!r->whole || v.shape == VarShape::scalar) {
      out.text += component_text(run, v, r->component, format);
      continue;
    }
    std::string t = v.shape == VarShape::colour ? "rgb(" : v.shape == VarShape::list ? "[" : "(";
    for (std::uint32_t k = 0; k < v.count; ++k) t += (k ? ", " : "") + component_text(run, v, k, format.empty() ? "exact" : format);
    out.text += t + (v.shape == VarShape::list ? "]" : ")");
  }
  return out;
}

std::string narrate(const Lesson& lesson, const TraceModel& run, std::size_t step) {
  const Narration* n = lesson.section_for(run, step);
  return n ? fill_templates(n->text, run, step).text : std::string();
}

}  // namespace sw::vis
