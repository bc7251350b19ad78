#include "tracer/ray_tree.hpp"
#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>
#include "tracer/whitted.hpp"

namespace sw::tracer {

std::string_view kind_name(RayNode::Kind k) {
  constexpr std::string_view names[] = {"primary", "mirror", "transmitted", "shadow"};
  return names[static_cast<int>(k)];
}

namespace {

using V3 = std::array<double, 3>;

// The colour the step records: its last colour variable (the caustic step records E, then c).
std::optional<V3> step_colour(const TraceView& t, const StepRecord& st) {
  std::optional<V3> c;
  for (std::uint32_t v = st.var_begin; v < st.var_end; ++v)
    if (const VarRecord& r = t.var_at(v); r.shape == VarShape::colour && r.count == 3)
      c = V3{t.component_double(r, 0), t.component_double(r, 1), t.component_double(r, 2)};
  return c;
}

// The step's first item of one of these kinds, or nullptr.
const GeoRecord* step_item(const TraceView& t, const StepRecord& st, std::initializer_list<GeoKind> kinds) {
  for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g)
    for (GeoKind k : kinds)
      if (t.geo_at(g).kind == k) return &t.geo_at(g);
  return nullptr;
}

V3 item_point(const TraceView& t, const GeoRecord& g, int first) {
  return {t.geo_double(g, first), t.geo_double(g, first + 1), t.geo_double(g, first + 2)};
}

// The light a shadow ray runs to: a segment ends at its point or spot light; a ray (towards a
// directional light, at infinity) has that light's direction.
std::int64_t light_of(const TraceView& t, const GeoRecord& g, std::span<const lighting::Light<Rational>> lights) {
  const bool to_point = g.kind == GeoKind::segment3;
  const V3 q = item_point(t, g, 3);  // the segment's end, or the ray's direction
  std::int64_t best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < lights.size(); ++i) {
    if ((lights[i].type != lighting::LightType::directional) != to_point) continue;
    const V3 w{lights[i].where.x.get_d(), lights[i].where.y.get_d(), lights[i].where.z.get_d()};
    double d = 0;
    if (to_point) {
      for (int k = 0; k < 3; ++k) d += (w[k] - q[k]) * (w[k] - q[k]);
    } else {  // the angle between the directions: 1 - cos
      double wq = 0, ww = 0, qq = 0;
      for (int k = 0; k < 3; ++k) wq += w[k] * q[k], ww += w[k] * w[k], qq += q[k] * q[k];
      d = 1 - wq / std::sqrt(ww * qq);
    }
    if (d < best_d) best = std::int64_t(i), best_d = d;
  }
  return best;
}

}  // namespace

std::vector<RayNode> ray_tree(const TraceView& t, std::span<const lighting::Light<Rational>> lights) {
  using L = Whitted;
  std::vector<RayNode> tree;
  std::vector<int> open;  // the rays whose steps are running, innermost last
  RayNode::Kind next = RayNode::Kind::primary;
  double next_weight = 1;  // the next ray's path weight: its parent's times the factor cast with
  for (std::size_t s = 0; s < t.size(); ++s) {
    const StepRecord& st = t.at(s);
    if (st.scope != 0 && t.scope_id(st.scope) != Whitted::id) continue;
    RayNode* here = open.empty() ? nullptr : &tree[std::size_t(open.back())];
    switch (st.line) {
      case L::closest: {
        RayNode n;
        n.kind = here ? next : RayNode::Kind::primary;
        n.parent = here ? open.back() : -1;
        n.depth = int(open.size()) + 1;
        n.weight = here ? next_weight : 1;
        n.step = s, n.hit = st.kind == StepKind::hit;
        if (const GeoRecord* g = n.hit ? step_item(t, st, {GeoKind::segment3}) : nullptr) n.at = item_point(t, *g, 3);
        open.push_back(int(tree.size()));
        tree.push_back(n);
        break;
      }
      case L::shadow: {
        if (!here) break;
        RayNode n;
        n.kind = RayNode::Kind::shadow, n.parent = open.back(), n.step = n.end = s, n.depth = here->depth,
        n.weight = here->weight;
        n.hit = st.kind == StepKind::hit, n.returned = true;
        if (const GeoRecord* g = step_item(t, st, {GeoKind::segment3, GeoKind::ray3}))
          n.at = item_point(t, *g, 0), n.light = light_of(t, *g, lights);
        tree.push_back(n);
        break;
      }
      case L::local:
      case L::caustic:  // the caustic term added to the local colour
        if (const auto c = step_colour(t, st); here && c) here->local = *c;
        break;
      case L::background:
      case L::deep:
      case L::done:
        if (!here) break;
        if (const auto c = step_colour(t, st)) {
          here->colour = *c;
          if (st.line == L::background) here->local = *c;
        }
        here->returned = true, here->end = s;
        open.pop_back();
        break;
      case L::reflect:
      case L::transmit:
        if (const GeoRecord* g = step_item(t, st, {GeoKind::ray3}); here && g) {
          next = st.line == L::reflect ? RayNode::Kind::mirror : RayNode::Kind::transmitted;
          next_weight = here->weight * t.geo_value(*g).value_or(0);
        }
        break;
      default: break;
    }
  }
  for (RayNode& n : tree)
    if (n.kind != RayNode::Kind::shadow)
      for (std::size_t k = 0; k < 3; ++k) n.added[k] = n.weight * n.local[k];
  return tree;
}

std::array<double, 3> ray_tree_sum(const std::vector<RayNode>& tree) {
  std::array<double, 3> sum{};
  for (const RayNode& n : tree)
    for (std::size_t k = 0; k < 3; ++k) sum[k] += n.added[k];
  return sum;
}

}  // namespace sw::tracer
