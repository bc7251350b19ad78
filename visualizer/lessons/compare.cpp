#include "lessons/compare.hpp"
#include <algorithm>
#include <iterator>

namespace sw::vis {

std::string Comparison::label() const {
  if (!numeric) return "";
  const std::string n(numeric_name(*numeric));
  return other ? std::string(other->id) + " (" + n + ")" : n;
}

Comparison parse_comparison(const Algorithm& alg, std::string_view name, Numeric numeric) {
  if (!alg.compare_group.empty())
    for (const Algorithm& a : catalog())
      if (a.id == name && &a != &alg && a.compare_group == alg.compare_group) return {numeric, &a};
  try {
    return {parse_numeric_for(alg, name)};
  } catch (const InputError& e) {
    if (alg.compare_group.empty()) throw;
    std::string others;
    for (const Algorithm& a : catalog())
      if (&a != &alg && a.compare_group == alg.compare_group) others += (others.empty() ? "" : ", ") + std::string(a.id);
    throw InputError(std::string(e.what()) + "; or another of the " + std::string(alg.compare_group) + ": " + others);
  }
}

Json carried_input(const Json& input, const Json& previous) {
  Json out = previous;
  if (!input.is_object() || !out.is_object()) return out;
  for (auto it = out.begin(); it != out.end(); ++it)
    if (input.contains(it.key())) it.value() = input[it.key()];
  return out;
}
namespace {

bool same_decisions(const TraceView& a, const TraceView& b, std::size_t s) {
  if (s >= a.size() || s >= b.size()) return false;
  const StepRecord &x = a.at(s), &y = b.at(s);
  if (x.line != y.line || x.kind != y.kind || x.scope != y.scope) return false;
  if (x.var_end - x.var_begin != y.var_end - y.var_begin || x.geo_end - x.geo_begin != y.geo_end - y.geo_begin) return false;
  for (std::uint32_t k = 0; k < x.var_end - x.var_begin; ++k) {
    const VarRecord &u = a.var_at(x.var_begin + k), &v = b.var_at(y.var_begin + k);
    if (u.is_int != v.is_int) return false;
    if (u.is_int && u.count != v.count) return false;
    for (std::uint32_t c = 0; u.is_int && c < u.count; ++c)  // integers, and every entry of an integer list
      if (a.int_value(u.slot + c) != b.int_value(v.slot + c)) return false;
  }
  for (std::uint32_t k = 0; k < x.geo_end - x.geo_begin; ++k) {
    const GeoRecord &g = a.geo_at(x.geo_begin + k), &h = b.geo_at(y.geo_begin + k);
    if (g.kind != h.kind || g.count != h.count) return false;
    if (geo_desc(g.kind).decision)  // the vocabulary's rule, as in `check --decisions-only`
      for (std::uint32_t c = 0; c < g.count; ++c)
        if (a.int_value(g.slot + c) != b.int_value(h.slot + c)) return false;
  }
  return true;
}

bool same_values(const TraceView& a, const TraceView& b, std::size_t s) {
  const StepRecord &x = a.at(s), &y = b.at(s);
  for (std::uint32_t k = 0; k < x.var_end - x.var_begin; ++k) {
    const VarRecord &u = a.var_at(x.var_begin + k), &v = b.var_at(y.var_begin + k);
    if (u.is_int || u.count != v.count) continue;
    for (std::uint32_t c = 0; c < u.count; ++c)
      if (a.num_double(u.slot + c) != b.num_double(v.slot + c)) return false;
  }
  return true;
}

}  // namespace

bool same_decisions_at(const TraceModel& a, const TraceModel& b, std::size_t s) { return same_decisions(a.trace(), b.trace(), s); }

CompareStats compare_traces(const TraceModel& a, const TraceModel& b) {
  CompareStats st;
  st.steps_a = a.size(), st.steps_b = b.size();
  st.pixels_a = a.plots().size(), st.pixels_b = b.plots().size();
  const std::size_t common = std::min(a.size(), b.size());
  for (std::size_t s = 0; s < common; ++s) {
    const bool decisions = same_decisions_at(a, b, s);
    if (!st.first_value_divergence && (!decisions || !same_values(a.trace(), b.trace(), s))) st.first_value_divergence = s;
    if (!decisions) {
      if (!st.first_decision_divergence) st.first_decision_divergence = s;
      if (st.divergences.size() < CompareStats::kMaxListed) st.divergences.push_back(std::uint32_t(s));
    }
  }
  if (!st.first_decision_divergence && a.size() != b.size()) st.first_decision_divergence = common;
  if (!st.first_value_divergence) st.first_value_divergence = st.first_decision_divergence;
  // Symmetric difference of the plotted cell multisets.
  auto cells = [](const TraceModel& m) {
    std::vector<Pixel> c;
    c.reserve(m.plots().size());
    for (const PlotEvent& e : m.plots()) c.push_back(e.cell);
    std::sort(c.begin(), c.end());
    return c;
  };
  auto ca = cells(a), cb = cells(b);
  std::size_t i = 0, j = 0;
  while (i < ca.size() || j < cb.size()) {
    if (j == cb.size() || (i < ca.size() && ca[i] < cb[j])) ++st.pixel_mismatches, ++i;
    else if (i == ca.size() || cb[j] < ca[i]) ++st.pixel_mismatches, ++j;
    else ++i, ++j;
  }
  // The cells themselves: plotted by one run and never by the other.
  std::vector<Pixel> ua(ca.begin(), std::unique(ca.begin(), ca.end())), ub(cb.begin(), std::unique(cb.begin(), cb.end()));
  std::set_symmetric_difference(ua.begin(), ua.end(), ub.begin(), ub.end(), std::back_inserter(st.mismatched_cells));
  if (st.mismatched_cells.size() > CompareStats::kMaxListed) st.mismatched_cells.resize(CompareStats::kMaxListed);
  return st;
}

}  // namespace sw::vis
