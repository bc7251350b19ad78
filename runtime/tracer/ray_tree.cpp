#include "tracer/ray_tree.hpp"
#include <cstring>
#include "tracer/whitted.hpp"

namespace sw::tracer {

std::string_view kind_name(RayNode::Kind k) {
  constexpr std::string_view names[] = {"primary", "mirror", "transmitted", "shadow"};
  return names[static_cast<int>(k)];
}

namespace {

const VarRecord* var(const TraceView& t, const StepRecord& st, const char* name) {
  for (std::uint32_t v = st.var_begin; v < st.var_end; ++v)
    if (std::strcmp(t.var_at(v).name, name) == 0) return &t.var_at(v);
  return nullptr;
}
double num(const TraceView& t, const StepRecord& st, const char* name) {
  const VarRecord* v = var(t, st, name);
  return v ? t.value_double(*v) : 0;
}
std::array<double, 3> rgb(const TraceView& t, const StepRecord& st, const char* name) {
  const VarRecord* v = var(t, st, name);
  if (!v || v->count != 3) return {};
  return {t.component_double(*v, 0), t.component_double(*v, 1), t.component_double(*v, 2)};
}

}  // namespace

std::vector<RayNode> ray_tree(const TraceView& t) {
  using L = Whitted;
  std::vector<RayNode> tree;
  std::vector<int> open;  // the rays whose steps are running, innermost last
  RayNode::Kind next = RayNode::Kind::primary;
  for (std::size_t s = 0; s < t.size(); ++s) {
    const StepRecord& st = t.at(s);
    if (st.scope != 0 && t.scope_id(st.scope) != Whitted::id) continue;
    switch (st.line) {
      case L::closest: {
        RayNode n;
        n.kind = open.empty() ? RayNode::Kind::primary : next;
        n.parent = open.empty() ? -1 : open.back();
        n.step = s, n.depth = int(num(t, st, "depth")), n.weight = num(t, st, "weight");
        n.hit = st.kind == StepKind::hit, n.object = std::int64_t(num(t, st, "object"));
        open.push_back(int(tree.size()));
        tree.push_back(n);
        break;
      }
      case L::shadow: {
        if (open.empty()) break;
        const RayNode& at = tree[std::size_t(open.back())];
        RayNode n;
        n.kind = RayNode::Kind::shadow, n.parent = open.back(), n.step = s, n.depth = at.depth, n.weight = at.weight;
        n.hit = num(t, st, "blocked") != 0, n.light = std::int64_t(num(t, st, "i")), n.returned = true, n.end = s;
        tree.push_back(n);
        break;
      }
      case L::local:
      case L::background:
        if (!open.empty()) tree[std::size_t(open.back())].local = rgb(t, st, "c");
        if (st.line == L::local) break;
        [[fallthrough]];
      case L::deep:
      case L::done:
        if (open.empty()) break;
        tree[std::size_t(open.back())].colour = rgb(t, st, "c");
        tree[std::size_t(open.back())].returned = true;
        tree[std::size_t(open.back())].end = s;
        open.pop_back();
        break;
      case L::reflect: next = RayNode::Kind::mirror; break;
      case L::transmit: next = RayNode::Kind::transmitted; break;
      default:
        // Any later line that records c (caustics) updates the local colour before the children.
        if (!open.empty() && var(t, st, "c")) tree[std::size_t(open.back())].local = rgb(t, st, "c");
        break;
    }
  }
  for (RayNode& n : tree)
    if (n.kind != RayNode::Kind::shadow)
      for (int k = 0; k < 3; ++k) n.added[std::size_t(k)] = n.weight * n.local[std::size_t(k)];
  return tree;
}

std::array<double, 3> ray_tree_sum(const std::vector<RayNode>& tree) {
  std::array<double, 3> sum{};
  for (const RayNode& n : tree)
    for (std::size_t k = 0; k < 3; ++k) sum[k] += n.added[k];
  return sum;
}

}  // namespace sw::tracer
