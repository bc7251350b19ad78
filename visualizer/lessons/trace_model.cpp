#include "lessons/trace_model.hpp"
#include <algorithm>
#include <cmath>
#include <cstring>

namespace sw::vis {

void WorldRect::add(double x, double y) {
  if (empty()) {
    *this = {x, y, x, y};
    return;
  }
  x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
}

TraceModel::TraceModel(Run run, Recorded rec) : run_(std::move(run)), rec_(std::move(rec)) {
  const Algorithm& alg = run_.algorithm();
  bounds_ = {1, 1, 0, 0};  // empty
  // Where the declared 2D handles are, read from the input once; they are framed too (control
  // points may lie off the curve).
  for (const Handle& h : alg.handles) {
    handles_.emplace_back();
    if (h.kind != Handle::Kind::point2) continue;
    try {
      const Json& v = run_.input().at(Json::json_pointer(h.pointer));
      if (v.is_array() && v.size() == 2) handles_.back() = std::array<double, 2>{parse_rational(v[0], h.label).get_d(), parse_rational(v[1], h.label).get_d()};
    } catch (const std::exception&) {
    }
    if (handles_.back()) bounds_.add((*handles_.back())[0], (*handles_.back())[1]);
  }
  const TraceView& t = *rec_.trace;
  const std::size_t n = t.size();
  // The algorithm's own listing: scope 0, or a recursive call of itself (a ray tracer's mirror
  // rays), whose kept items are the algorithm's to show and last.
  auto own = [&](std::uint8_t scope) { return scope == 0 || t.scope_id(scope) == alg.id; };
  name_of_var_.resize(n ? t.at(n - 1).var_end : 0);
  for (std::size_t s = 0; s < n; ++s) {
    const StepRecord& st = t.at(s);
    for (std::uint32_t v = st.var_begin; v < st.var_end; ++v) {
      const VarRecord& var = t.var_at(v);
      if (var.shape != VarShape::colour) continue;
      std::uint32_t rgba = 0xff000000u;
      for (std::uint32_t c = 0; c < 3; ++c) {
        const double x = t.component_double(var, c);
        rgba |= std::uint32_t(std::lround(255 * std::clamp(std::isfinite(x) ? x : 0.0, 0.0, 1.0))) << (8 * c);
      }
      step_rgba_.resize(n, 0u);
      step_rgba_[s] = rgba;
    }
    for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g) {
      const GeoRecord& geo = t.geo_at(g);
      if (geo.life != Life::step) lasting_.push_back(g), lasting_end_.push_back(own(st.scope) ? kNoStep : static_cast<std::uint32_t>(s));
      if (geo.kind == GeoKind::pixel) {
        const Pixel p{t.int_value(geo.slot), t.int_value(geo.slot + 1)};
        plots_.push_back({p, static_cast<std::uint32_t>(s)});
        bounds_.add(double(p.x) - 0.5, double(p.y) - 0.5);
        bounds_.add(double(p.x) + 0.5, double(p.y) + 0.5);
      } else if (geo.kind == GeoKind::span) {  // row j, columns i0..i1: each a plotted pixel (a fill's spans)
        const std::int64_t j = t.int_value(geo.slot), i0 = t.int_value(geo.slot + 1), i1 = t.int_value(geo.slot + 2);
        for (std::int64_t i = i0; i <= i1; ++i) plots_.push_back({Pixel{i, j}, static_cast<std::uint32_t>(s)});
        if (i0 <= i1) bounds_.add(double(i0) - 0.5, double(j) - 0.5), bounds_.add(double(i1) + 0.5, double(j) + 0.5);
      } else if (geo.kind == GeoKind::circle) {
        const double x = t.geo_double(geo, 0), y = t.geo_double(geo, 1), r = t.geo_double(geo, 2);
        bounds_.add(x - r, y - r);
        bounds_.add(x + r, y + r);
      } else if (geo.kind == GeoKind::node2) {  // id, parent, then the bounds
        bounds_.add(t.geo_double(geo, 2), t.geo_double(geo, 3));
        bounds_.add(t.geo_double(geo, 4), t.geo_double(geo, 5));
      } else if (geo_desc(geo.kind).dim == 2 && !geo_desc(geo.kind).integer) {  // points, segments, lists: coordinate pairs
        for (std::uint32_t k = 0; k + 1 < geo.count; k += 2) bounds_.add(t.geo_double(geo, int(k)), t.geo_double(geo, int(k) + 1));
      }
    }
    // Names are string literals; compare contents so that equal names from two sites merge.
    for (std::uint32_t v = st.var_begin; v < st.var_end; ++v) {
      const std::string_view name = t.var_at(v).name;
      auto it = std::find(names_.begin(), names_.end(), name);
      if (it == names_.end()) {
        if (names_.size() == 255) throw InputError(std::string(alg.id) + ": more than 255 variable names in one trace");
        names_.push_back(name);
        it = names_.end() - 1;
      }
      name_of_var_[v] = static_cast<std::uint8_t>(it - names_.begin());
    }
  }
  // A nested item (its step stored above) ends at the next step of the algorithm's own listing;
  // none: it lasts.
  std::vector<std::uint32_t> next_own(n, kNoStep);
  for (std::size_t s = n; s-- > 1;) next_own[s - 1] = own(t.at(s).scope) ? static_cast<std::uint32_t>(s) : next_own[s];
  for (std::uint32_t& end : lasting_end_)
    if (end != kNoStep) end = next_own[end];
  // Checkpoint c holds, per name, the latest var record among steps [0, c * kCheckpoint).
  std::vector<std::uint32_t> latest(names_.size(), kNoStep);
  for (std::size_t s = 0; s <= n; ++s) {
    if (s % kCheckpoint == 0) checkpoints_.insert(checkpoints_.end(), latest.begin(), latest.end());
    if (s < n) apply_step(s, latest);
  }
  by_cell_ = plots_;
  std::stable_sort(by_cell_.begin(), by_cell_.end(), [](const PlotEvent& a, const PlotEvent& b) { return a.cell < b.cell; });
}

void TraceModel::apply_step(std::size_t step, std::vector<std::uint32_t>& latest) const {
  const StepRecord& st = rec_.trace->at(step);
  for (std::uint32_t v = st.var_begin; v < st.var_end; ++v) latest[name_of_var_[v]] = v;
}

std::size_t TraceModel::plots_through(std::size_t step) const {
  auto it = std::upper_bound(plots_.begin(), plots_.end(), step, [](std::size_t s, const PlotEvent& e) { return s < e.step; });
  return static_cast<std::size_t>(it - plots_.begin());
}

std::uint32_t TraceModel::step_of_cell(Pixel c) const {
  auto it = std::lower_bound(by_cell_.begin(), by_cell_.end(), c, [](const PlotEvent& e, const Pixel& p) { return e.cell < p; });
  return it != by_cell_.end() && it->cell == c ? it->step : kNoStep;
}

std::optional<std::array<double, 2>> TraceModel::point_at(std::size_t step, const char** label) const {
  const TraceView& t = *rec_.trace;
  if (!size()) return std::nullopt;
  step = std::min(step, last());
  for (std::size_t k = 0; k <= 64 && k <= step; ++k) {
    const StepRecord& st = t.at(step - k);
    for (std::uint32_t g = st.geo_end; g-- > st.geo_begin;) {
      const GeoRecord& geo = t.geo_at(g);
      if (geo.kind != GeoKind::point2) continue;
      if (label) *label = geo.label;
      return std::array<double, 2>{t.geo_double(geo, 0), t.geo_double(geo, 1)};
    }
  }
  return std::nullopt;
}

std::optional<Pixel> TraceModel::pixel_at(std::size_t step) const {
  if (step >= size()) return std::nullopt;
  const TraceView& t = *rec_.trace;
  const StepRecord& st = t.at(step);
  for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g) {
    const GeoRecord& geo = t.geo_at(g);
    if (geo.kind == GeoKind::pixel) return Pixel{t.int_value(geo.slot), t.int_value(geo.slot + 1)};
  }
  return std::nullopt;
}

std::vector<std::uint32_t> TraceModel::visible_items(std::size_t step) const {
  std::vector<std::uint32_t> out;
  if (!size()) return out;
  const TraceView& t = *rec_.trace;
  const StepRecord& st = t.at(std::min(step, last()));
  auto add = [&](std::uint32_t g) {
    const GeoRecord& geo = t.geo_at(g);
    if (geo.life == Life::replace && geo.label)  // it takes the place of the earlier item so labelled
      for (std::uint32_t& k : out)
        if (k != kNoStep && t.geo_at(k).life == Life::replace && t.geo_at(k).label && std::strcmp(t.geo_at(k).label, geo.label) == 0) k = kNoStep;
    out.push_back(g);
  };
  // Geometry indices grow with the step, so the lasting items before this step are a prefix.
  for (std::size_t i = 0; i < lasting_.size() && lasting_[i] < st.geo_begin; ++i)
    if (step < lasting_end_[i]) add(lasting_[i]);
  for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g) add(g);
  std::erase(out, kNoStep);
  return out;
}

std::optional<double> value_difference(const VarState& a, const VarState& b) {
  if (a.parts.empty() && b.parts.empty()) return std::fabs(a.value - b.value);
  if (a.parts.size() != b.parts.size()) return std::nullopt;
  double most = 0;
  for (std::size_t k = 0; k < a.parts.size(); ++k)
    if (const double d = std::fabs(a.parts[k] - b.parts[k]); std::isnan(d) || d > most) most = d;  // NaN stays
  return most;
}

std::vector<VarState> TraceModel::state_at(std::size_t step) const {
  std::vector<VarState> out;
  if (!size()) return out;
  step = std::min(step, last());
  const std::size_t c = step / kCheckpoint;
  std::vector<std::uint32_t> before(checkpoints_.begin() + c * names_.size(), checkpoints_.begin() + (c + 1) * names_.size());
  for (std::size_t s = c * kCheckpoint; s < step; ++s) apply_step(s, before);
  std::vector<std::uint32_t> now = before;
  apply_step(step, now);
  const TraceView& t = *rec_.trace;
  const StepRecord& st = t.at(step);
  for (std::size_t k = 0; k < names_.size(); ++k) {
    if (now[k] == kNoStep) continue;
    const VarRecord& v = t.var_at(now[k]);
    VarState vs{names_[k], t.value_text(v), t.value_double(v), v.is_int, now[k] >= st.var_begin && now[k] < st.var_end, false};
    vs.changed = before[k] == kNoStep || (vs.set_here && t.value_text(t.var_at(before[k])) != vs.text);
    vs.shape = v.shape;
    if (v.shape == VarShape::colour)
      for (std::uint32_t c = 0; c < 3; ++c) vs.rgb[c] = static_cast<float>(t.component_double(v, c));
    if (v.shape != VarShape::scalar)
      for (std::uint32_t c = 0; c < v.count; ++c) vs.parts.push_back(t.component_double(v, c));
    out.push_back(std::move(vs));
  }
  return out;
}

const VarRecord* TraceModel::latest_var(std::size_t step, std::string_view name) const {
  if (!size()) return nullptr;
  step = std::min(step, last());
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) return nullptr;
  const auto k = static_cast<std::size_t>(it - names_.begin());
  const TraceView& t = *rec_.trace;
  const std::uint8_t scope = t.at(step).scope;
  // The steps [stop, step], newest first: the first record in the step's own scope wins, else the
  // newest of any scope.
  const std::size_t stop = step + 1 > kScopeScan ? step + 1 - kScopeScan : 0;
  const VarRecord* any = nullptr;
  for (std::size_t s = step + 1; s-- > stop;) {
    const StepRecord& st = t.at(s);
    for (std::uint32_t v = st.var_end; v-- > st.var_begin;)
      if (name_of_var_[v] == k) {
        if (st.scope == scope) return &t.var_at(v);
        if (!any) any = &t.var_at(v);
      }
  }
  if (any || stop == 0) return any;
  // Before the scan: the newest record, from the checkpoint at or before `stop` (it holds steps
  // before its own start) and the steps from there to `stop`.
  const std::size_t c = stop / kCheckpoint;
  std::uint32_t latest = checkpoints_[c * names_.size() + k];
  for (std::size_t s = c * kCheckpoint; s < stop; ++s) {
    const StepRecord& st = t.at(s);
    for (std::uint32_t v = st.var_begin; v < st.var_end; ++v)
      if (name_of_var_[v] == k) latest = v;
  }
  return latest == kNoStep ? nullptr : &t.var_at(latest);
}

std::optional<std::size_t> TraceModel::find_kind(std::size_t from, StepKind kind, bool forward) const {
  const TraceView& t = *rec_.trace;
  if (forward) {
    for (std::size_t s = from + 1; s < size(); ++s)
      if (t.at(s).kind == kind) return s;
  } else {
    for (std::size_t s = std::min(from, size()); s-- > 0;)
      if (t.at(s).kind == kind) return s;
  }
  return std::nullopt;
}

std::optional<std::size_t> TraceModel::step_over(std::size_t from, bool forward) const {
  const TraceView& t = *rec_.trace;
  if (from >= size()) return std::nullopt;
  const std::uint8_t here = t.at(from).scope;
  auto in_view = [&](std::size_t s) { return t.at(s).scope == here || t.at(s).scope == 0; };
  if (forward) {
    for (std::size_t s = from + 1; s < size(); ++s)
      if (in_view(s)) return s;
  } else {
    for (std::size_t s = from; s-- > 0;)
      if (in_view(s)) return s;
  }
  return std::nullopt;
}

std::shared_ptr<const TraceModel> record_model(const Run& run, const Budget& budget) {
  run.check_budget(budget);
  Recorded rec = run.record();
  if (!rec.trace || rec.trace->size() == 0) throw InputError(std::string(run.algorithm().id) + ": the run recorded no steps");
  return std::make_shared<const TraceModel>(run, std::move(rec));
}

std::shared_ptr<const TraceModel> record_model(const Algorithm& alg, const Json& input, Numeric numeric, const Budget& budget) {
  return record_model(alg.open(input, numeric), budget);
}

}  // namespace sw::vis
