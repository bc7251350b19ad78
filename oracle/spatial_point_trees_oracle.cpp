#include "spatial_point_trees_oracle.hpp"
#include <algorithm>
#include <functional>

namespace sw::oracle {
namespace {

struct Builder {
  CellSpecTree t;
  std::size_t cap;
  int max_depth;
  std::size_t max_refs, refs = 0;
  std::size_t fanout;
  // Which items the cell holds, by testing every item.
  std::function<std::vector<std::int32_t>(const std::vector<Rational>&, const std::vector<Rational>&, const std::vector<bool>&)> members;

  void cell(std::size_t id, const std::vector<bool>& closed, int depth) {
    const std::vector<Rational> lo = t.nodes[id].lo, hi = t.nodes[id].hi;
    std::vector<std::int32_t> items = members(lo, hi, closed);
    const std::size_t d = lo.size(), k = std::size_t{1} << d;
    const bool over = items.size() > cap && depth < max_depth;
    if (!over || refs + fanout * items.size() > max_refs) {
      t.budget_stops += over;
      t.depth = std::max<std::size_t>(t.depth, static_cast<std::size_t>(depth));
      t.nodes[id].items = std::move(items);
      return;
    }
    const std::size_t first = t.nodes.size();
    std::vector<std::vector<bool>> child_closed(k, closed);
    refs -= items.size();
    for (std::size_t c = 0; c < k; ++c) {
      CellSpecNode n;
      n.parent = static_cast<std::int32_t>(id), n.lo = lo, n.hi = hi;
      for (std::size_t a = 0; a < d; ++a) {
        const Rational mid = (lo[a] + hi[a]) / 2;
        (c >> a & 1 ? n.lo : n.hi)[a] = mid;
        child_closed[c][a] = (c >> a & 1) && closed[a];
      }
      t.nodes[id].children.push_back(static_cast<std::int32_t>(first + c));
      t.nodes.push_back(std::move(n));
    }
    // The leaf entries the children take: counted before any of them splits (as the build does).
    for (std::size_t c = 0; c < k; ++c) refs += members(t.nodes[first + c].lo, t.nodes[first + c].hi, child_closed[c]).size();
    for (std::size_t c = 0; c < k; ++c) cell(first + c, child_closed[c], depth + 1);
  }
};

}  // namespace

CellSpecTree point_cell_tree(const std::vector<std::vector<Rational>>& points, std::size_t cap, int max_depth, std::size_t max_refs) {
  Builder b{{}, cap, max_depth, max_refs, points.size(), 1, {}};
  const std::size_t d = points[0].size();
  b.members = [&](const std::vector<Rational>& lo, const std::vector<Rational>& hi, const std::vector<bool>& closed) {
    std::vector<std::int32_t> in;
    for (std::size_t i = 0; i < points.size(); ++i) {
      bool ok = true;
      for (std::size_t a = 0; a < d && ok; ++a) ok = lo[a] <= points[i][a] && (points[i][a] < hi[a] || (closed[a] && points[i][a] == hi[a]));
      if (ok) in.push_back(static_cast<std::int32_t>(i));
    }
    return in;
  };
  CellSpecNode root;
  root.lo = root.hi = points[0];
  for (const auto& p : points)
    for (std::size_t a = 0; a < d; ++a) root.lo[a] = std::min(root.lo[a], p[a]), root.hi[a] = std::max(root.hi[a], p[a]);
  b.t.nodes.push_back(root);
  b.cell(0, std::vector<bool>(d, true), 0);
  return b.t;
}

CellSpecTree triangle_cell_tree(const std::vector<Triangle3>& tris, std::size_t cap, int max_depth, std::size_t max_refs) {
  Builder b{{}, cap, max_depth, max_refs, tris.size(), 8, {}};
  b.members = [&](const std::vector<Rational>& lo, const std::vector<Rational>& hi, const std::vector<bool>&) {
    std::vector<std::int32_t> in;
    const Vec3<Rational> l{lo[0], lo[1], lo[2]}, h{hi[0], hi[1], hi[2]};
    for (std::size_t i = 0; i < tris.size(); ++i) {
      // Disjoint bounding boxes cannot meet: spares CGAL most pairs.
      bool near = true;
      for (int a = 0; a < 3; ++a)
        near = near && std::min({tris[i][0][a], tris[i][1][a], tris[i][2][a]}) <= h[a] && l[a] <= std::max({tris[i][0][a], tris[i][1][a], tris[i][2][a]});
      if (near && triangle_meets_box(tris[i], l, h)) in.push_back(static_cast<std::int32_t>(i));
    }
    return in;
  };
  CellSpecNode root;
  root.lo = root.hi = {tris[0][0].x, tris[0][0].y, tris[0][0].z};
  for (const auto& t : tris)
    for (const auto& v : t)
      for (int a = 0; a < 3; ++a) root.lo[a] = std::min(root.lo[a], v[a]), root.hi[a] = std::max(root.hi[a], v[a]);
  b.t.nodes.push_back(root);
  b.cell(0, std::vector<bool>(3, true), 0);
  return b.t;
}

}  // namespace sw::oracle
