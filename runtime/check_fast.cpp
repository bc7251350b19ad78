// `check`'s fast path for one step: the replay's line and the trace's read flat (flat_json.hpp) and
// compared without building JSON trees. It says "agrees" only where require_step_shape and
// step_diff would find nothing; anything else (a difference, a value only exact arithmetic can
// judge, a text the flat reader refuses) goes to them, which decide and name the problem.
#include <algorithm>
#include "check_step.hpp"

namespace sw::check_values {

namespace {

using T = FlatJson::Type;
using Index = std::uint32_t;

bool is_modifier(std::string_view key) { return key == "label" || key == "life" || key == "value"; }
bool is_scalar(const FlatJson::Node& n) { return n.type == T::integer || n.type == T::number || n.type == T::string; }

// A string that parse_rational reads in a trace: a subset of its syntax, [+-]digits, optionally
// "/digits" with a nonzero denominator or ".digits".
bool exact_text(std::string_view s) {
  if (s.size() > kMaxExactTextChars) return false;
  std::size_t i = !s.empty() && (s[0] == '-' || s[0] == '+');
  auto digits = [&] {
    const std::size_t from = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return s.substr(from, i - from);
  };
  if (digits().empty()) return false;
  if (i == s.size()) return true;
  if (s[i] == '.') return ++i, digits(), i == s.size();
  if (s[i] != '/') return false;
  ++i;
  const std::string_view q = digits();
  return !q.empty() && i == s.size() && q.find_first_not_of('0') != std::string_view::npos;
}
// A variable's or geometry value's scalar as require_step_shape takes it.
bool number_ok(const FlatJson& j, Index v) {
  const auto& n = j[v];
  return n.type == T::integer || n.type == T::number || (n.type == T::string && (is_nonfinite_text(n.text) || exact_text(n.text)));
}

// require_step_shape's rules, on the trace's line.
bool shape_ok(const FlatJson& j, bool geometry) {
  if (j[FlatJson::root].type != T::object) return false;
  const auto line = j.member(FlatJson::root, "line"), kind = j.member(FlatJson::root, "kind"), vars = j.member(FlatJson::root, "vars"), geo = j.member(FlatJson::root, "geo");
  if (!line || j[*line].type != T::integer || !kind || j[*kind].type != T::string || !vars || j[*vars].type != T::object) return false;
  if ((geometry || geo) && (!geo || j[*geo].type != T::array)) return false;
  if (geo) {
    Index item = j.first_element(*geo);
    for (Index n = 0; n < j[*geo].size; ++n, item = j.next_element(item)) {
      if (j[item].type != T::object) return false;
      std::size_t kinds = 0;
      Index k = j.first_member(item);
      for (Index m = 0; m < j[item].size; ++m, k = j.next_member(k)) {
        const std::string_view key = j[k].text;
        if (!is_modifier(key)) ++kinds;
        else if (key == "value") {
          if (!is_scalar(j[k + 1]) || !number_ok(j, k + 1)) return false;
        } else if (j[k + 1].type != T::string || (key == "life" && !parse_life(j[k + 1].text))) return false;
      }
      if (kinds != 1) return false;
    }
  }
  Index k = j.first_member(*vars);
  for (Index m = 0; m < j[*vars].size; ++m, k = j.next_member(k)) {
    Index list = k + 1;
    if (j[list].type == T::object) {
      const auto rgb = j[list].size == 1 ? j.member(list, "rgb") : std::nullopt;
      if (!rgb || j[*rgb].type != T::array || j[*rgb].size != 3) return false;
      list = *rgb;
    }
    if (j[list].type != T::array) {
      if (!is_scalar(j[list]) || !number_ok(j, list)) return false;
      continue;
    }
    if (j[list].size > kMaxListLength) return false;
    Index e = j.first_element(list);
    for (Index n = 0; n < j[list].size; ++n, e = j.next_element(e))
      if (!is_scalar(j[e]) || !number_ok(j, e)) return false;
  }
  return true;
}

std::optional<Approx> approx_of(const FlatJson& j, Index v) {
  if (j[v].type == T::string) return approx_text(j[v].text);
  if (const auto d = j.number(v)) return Approx{*d, 0};
  return std::nullopt;
}

// value_diff's rules where they find nothing: exact numbers with the same text, others surely
// within the tolerance by the filter; false for anything the exact comparison has to decide.
bool value_agrees(const FlatJson& w, Index a, const FlatJson& g, Index b, const Tolerance& tol, bool exact, std::size_t depth = 0) {
  const auto &x = w[a], &y = g[b];
  if (depth > kMaxNesting) return false;
  if (is_scalar(x) && is_scalar(y)) {
    const bool integer = x.type == T::integer;
    if (!exact && !tol.numbers && !integer) return true;  // --decisions-only
    if (x.type == y.type && x.text == y.text) return true;
    if (exact || integer) return false;
    const auto p = approx_of(w, a), q = approx_of(g, b);
    return p && q && surely_within(*p, *q, tol);
  }
  if (x.type != y.type) return false;
  if (x.type == T::array) {
    if (x.size != y.size) return false;
    for (Index n = 0, i = w.first_element(a), k = g.first_element(b); n < x.size; ++n, i = w.next_element(i), k = g.next_element(k))
      if (!value_agrees(w, i, g, k, tol, exact, depth + 1)) return false;
    return true;
  }
  if (x.type == T::object) {
    Index want_members = 0, got_members = 0;
    for (Index n = 0, k = w.first_member(a); n < x.size; ++n, k = w.next_member(k)) {
      if (w[k].text == "fallback") continue;  // informational
      const auto other = g.member(b, w[k].text);
      if (!other || !value_agrees(w, k + 1, g, *other, tol, exact, depth + 1)) return false;
      ++want_members;
    }
    for (Index n = 0, k = g.first_member(b); n < y.size; ++n, k = g.next_member(k)) got_members += g[k].text != "fallback";
    return want_members == got_members;  // no member the replay lacks (keys are unique)
  }
  return x.text == y.text;  // null, true, false
}

std::string_view string_member(const FlatJson& j, Index o, std::string_view name) {
  const auto m = j.member(o, name);
  return m && j[*m].type == T::string ? j[*m].text : std::string_view();
}

}  // namespace

bool step_agrees(const FlatJson& want, const FlatJson& got, std::size_t index, const Tolerance& tol, bool geometry) {
  constexpr Index root = FlatJson::root;
  if (want[root].type != T::object || got.member(root, "result") || !shape_ok(got, geometry)) return false;
  if (const auto step = got.member(root, "step")) {
    const auto n = got.number(*step);
    if (got[*step].type != T::integer || !n || *n != static_cast<double>(index)) return false;
  }
  if (string_member(want, root, "in") != string_member(got, root, "in")) return false;
  const auto wline = want.member(root, "line"), wkind = want.member(root, "kind"), wvars = want.member(root, "vars");
  if (!wline || !wkind || !wvars || want[*wline].type != T::integer || want[*wkind].type != T::string || want[*wvars].type != T::object) return false;
  if (want[*wline].text != got[*got.member(root, "line")].text || want[*wkind].text != got[*got.member(root, "kind")].text) return false;
  // Variables: the same names; integers (and integer lists) exactly, numbers within the tolerance.
  const Index gvars = *got.member(root, "vars");
  if (want[*wvars].size != got[gvars].size) return false;  // names are unique: equal counts and each found
  for (Index n = 0, k = want.first_member(*wvars); n < want[*wvars].size; ++n, k = want.next_member(k)) {
    const auto mine = got.member(gvars, want[k].text);
    if (!mine) return false;
    bool is_int = want[k + 1].type == T::integer;
    if (want[k + 1].type == T::array && want[k + 1].size > 0) {
      is_int = true;
      for (Index e = want.first_element(k + 1); e < want[k + 1].end; e = want.next_element(e)) is_int = is_int && want[e].type == T::integer;
    }
    if ((tol.numbers || is_int) && !value_agrees(want, k + 1, got, *mine, tol, is_int)) return false;
  }
  const auto ggeo = got.member(root, "geo");
  if (!ggeo) return true;  // left out, as --decisions-only allows
  const auto wgeo = want.member(root, "geo");
  if (!wgeo || want[*wgeo].type != T::array || want[*wgeo].size != got[*ggeo].size) return false;
  for (Index n = 0, a = want.first_element(*wgeo), b = got.first_element(*ggeo); n < want[*wgeo].size; ++n, a = want.next_element(a), b = got.next_element(b)) {
    if (want[a].type != T::object) return false;
    std::optional<Index> kind_key;  // the replay's item has one kind key
    for (Index m = 0, k = want.first_member(a); m < want[a].size; ++m, k = want.next_member(k))
      if (!is_modifier(want[k].text)) {
        if (kind_key) return false;
        kind_key = k;
      }
    if (!kind_key) return false;
    const auto mine = got.member(b, want[*kind_key].text);
    if (!mine) return false;
    const auto kind = parse_geo(want[*kind_key].text);
    const bool decision = kind && geo_desc(*kind).decision;
    if ((tol.numbers || decision) && !value_agrees(want, *kind_key + 1, got, *mine, tol, decision)) return false;
    for (const char* key : {"label", "life", "value"}) {
      const auto stated = got.member(b, key);
      if (!stated) continue;
      const auto recorded = want.member(a, key);
      if (!recorded) return false;
      if (std::string_view(key) != "value") {
        if (want[*recorded].type != T::string || want[*recorded].text != got[*stated].text) return false;
      } else if (tol.numbers && !value_agrees(want, *recorded, got, *stated, tol, false)) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace sw::check_values
