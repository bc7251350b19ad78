// What the kd-tree tests share: seeded meshes (random, and grids with shared vertices), the tree
// of a build's JSON result read back exactly, the structural invariants checked exactly (cells,
// the closed-cell reference rule with CGAL's triangle-box overlap, each point held once), and
// one prebuilt tree per mode for many queries (filtered: intervals, exact where they cannot decide).
#pragma once
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <optional>
#include <set>
#include "catalog.hpp"
#include "spatial/kd_common.hpp"
#include "spatial/kd_nearest.hpp"
#include "spatial/kd_traverse.hpp"
#include "spatial/mesh_json.hpp"
#include "spatial_oracle.hpp"

namespace sw::testing::kd {

using namespace sw::spatial;
using Q = Rational;

// Every input is refused by the algorithm's validation with one line.
inline void check_refused(const Algorithm& a, std::initializer_list<const char*> bad) {
  for (const char* in : bad) {
    INFO(in);
    try {
      (void)a.open(Json::parse(in), Numeric::exact);
      FAIL("accepted");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find('\n') == std::string::npos);
    }
  }
}

// An n x n grid of unit cells on z = z0 (scaled by s), two triangles per cell, vertices shared.
inline Mesh grid_mesh(int n, double s = 1, double z0 = 0) {
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.v.push_back({i * s, j * s, z0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::int32_t a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      m.f.push_back({a, b, c}), m.f.push_back({a, c, d});
    }
  return m;
}

using sw::testing::mesh_json;

inline Json ray_json(const RayIn& r) { return {{"o", {r.o[0], r.o[1], r.o[2]}}, {"d", {r.d[0], r.d[1], r.d[2]}}}; }

// A build's tree, read back exactly from its JSON result.
struct Node {
  std::int32_t parent = -1;
  std::vector<std::int32_t> children, prims;
  int axis = -1;
  std::array<Q, 3> lo, hi;
};
struct Tree {
  int dim = 3;
  std::size_t depth = 0, leaves = 0;
  std::vector<Node> nodes;
};
inline Tree read_tree(const Json& r) {
  Tree t;
  t.depth = r.at("depth").get<std::size_t>(), t.leaves = r.at("leaves").get<std::size_t>();
  for (const Json& n : r.at("tree")) {
    Node x;
    x.parent = n.at("parent").get<std::int32_t>();
    if (n.contains("children")) x.children = n["children"].get<std::vector<std::int32_t>>(), x.axis = n["axis"].get<int>();
    else x.prims = n.at("prims").get<std::vector<std::int32_t>>();
    t.dim = static_cast<int>(n.at("lo").size());
    for (int k = 0; k < t.dim; ++k) x.lo[k] = parse_rational(n["lo"][k], "lo"), x.hi[k] = parse_rational(n["hi"][k], "hi");
    t.nodes.push_back(std::move(x));
  }
  return t;
}

// Violations of the structure, counted (rounded modes may have some; robust ones none).
struct Violations {
  std::size_t cells = 0;    // a child's cell is not its parent's cut at one plane, or the root is not the bounds
  std::size_t missing = 0;  // a primitive meets a leaf's closed cell and the leaf does not hold it
  std::size_t extra = 0;    // a leaf holds a primitive whose bounds miss its cell
  std::size_t held = 0;     // a point held by no leaf or several, or outside its leaf's cell
  std::size_t planes = 0;   // a node's points on its plane split between both sides
  std::size_t shape = 0;    // depth beyond the bound, counts that disagree
  std::size_t total() const { return cells + missing + extra + held + planes + shape; }
};

inline bool in_box(const std::array<Q, 3>& p, const Node& n, int dim) {
  for (int k = 0; k < dim; ++k)
    if (p[k] < n.lo[k] || n.hi[k] < p[k]) return false;
  return true;
}

// Cells: the root is the primitives' bounds (given), the children cut the parent at one plane
// inside it; shape: depth and leaf counts against the tree and the documented bound.
inline void check_cells(const Tree& t, const std::array<Q, 3>& lo, const std::array<Q, 3>& hi, std::size_t n, Violations& v) {
  for (int k = 0; k < t.dim; ++k) v.cells += t.nodes[0].lo[k] != lo[k] || t.nodes[0].hi[k] != hi[k];
  std::size_t leaves = 0, depth = 0;
  std::vector<std::size_t> d(t.nodes.size(), 0);
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    const Node& p = t.nodes[i];
    if (p.children.empty()) {
      ++leaves, depth = std::max(depth, d[i]);
      continue;
    }
    if (p.children.size() != 2 || p.axis < 0 || p.axis >= t.dim) {
      ++v.cells;
      continue;
    }
    const Node &l = t.nodes[p.children[0]], &r = t.nodes[p.children[1]];
    d[p.children[0]] = d[p.children[1]] = d[i] + 1;
    const int a = p.axis;
    bool ok = l.parent == static_cast<std::int32_t>(i) && r.parent == static_cast<std::int32_t>(i) && l.hi[a] == r.lo[a] && p.lo[a] <= l.hi[a] && l.hi[a] <= p.hi[a];
    for (int k = 0; k < t.dim; ++k) ok = ok && l.lo[k] == p.lo[k] && r.hi[k] == p.hi[k] && (k == a || (l.hi[k] == p.hi[k] && r.lo[k] == p.lo[k]));
    v.cells += !ok;
  }
  v.shape += leaves != t.leaves || depth != t.depth || depth > static_cast<std::size_t>(kd_max_depth(n));
}

inline void check_triangle_tree(const Tree& t, const Mesh& m, Violations& v) {
  std::vector<oracle::Triangle3> tris;
  for (std::size_t i = 0; i < m.size(); ++i) tris.push_back(m.triangle<Q>(i));
  std::array<Q, 3> lo{tris[0][0].x, tris[0][0].y, tris[0][0].z}, hi = lo;
  for (const auto& tri : tris)
    for (const auto& p : tri)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  check_cells(t, lo, hi, m.size(), v);
  for (const Node& n : t.nodes) {
    if (!n.children.empty()) continue;
    const std::set<std::int32_t> held(n.prims.begin(), n.prims.end());
    const Vec3<Q> blo{n.lo[0], n.lo[1], n.lo[2]}, bhi{n.hi[0], n.hi[1], n.hi[2]};
    for (std::size_t i = 0; i < tris.size(); ++i) {
      const bool meets = oracle::triangle_meets_box(tris[i], blo, bhi);
      if (meets && !held.count(static_cast<std::int32_t>(i))) ++v.missing;
      if (held.count(static_cast<std::int32_t>(i))) {
        bool box_meets = true;  // the triangle's bounds meet the cell (closed)
        for (int k = 0; k < 3; ++k) {
          const Q a = std::min({tris[i][0][k], tris[i][1][k], tris[i][2][k]}), b = std::max({tris[i][0][k], tris[i][1][k], tris[i][2][k]});
          box_meets = box_meets && !(b < n.lo[k]) && !(n.hi[k] < a);
        }
        v.extra += !box_meets;
      }
    }
  }
}

// Points: each held by exactly one leaf, inside its closed cell; a leaf whose cell holds a point
// it does not hold has it on its boundary; at each inner node, the subtree's points on its plane
// all went to one side (the cheaper one).
inline void check_point_tree(const Tree& t, const std::vector<std::array<Q, 3>>& pts, Violations& v) {
  std::array<Q, 3> lo = pts[0], hi = pts[0];
  for (const auto& p : pts)
    for (int k = 0; k < t.dim; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  check_cells(t, lo, hi, pts.size(), v);
  std::vector<int> count(pts.size(), 0);
  std::vector<std::int32_t> leaf_of(pts.size(), -1);
  for (std::size_t i = 0; i < t.nodes.size(); ++i)
    for (std::int32_t p : t.nodes[i].prims) {
      ++count[p], leaf_of[p] = static_cast<std::int32_t>(i);
      v.held += !in_box(pts[p], t.nodes[i], t.dim);
    }
  for (int c : count) v.held += c != 1;
  auto interior = [&](const std::array<Q, 3>& p, const Node& n) {
    for (int k = 0; k < t.dim; ++k)
      if (!(n.lo[k] < p[k] && p[k] < n.hi[k])) return false;
    return true;
  };
  for (std::size_t i = 0; i < t.nodes.size(); ++i)
    if (t.nodes[i].children.empty())
      for (std::size_t p = 0; p < pts.size(); ++p)
        if (leaf_of[p] != static_cast<std::int32_t>(i) && interior(pts[p], t.nodes[i])) ++v.held;
  // The side of each point at each ancestor: by walking up from its leaf.
  for (std::size_t i = 0; i < t.nodes.size(); ++i) {
    const Node& n = t.nodes[i];
    if (n.children.empty()) continue;
    const Q p = t.nodes[n.children[0]].hi[n.axis];
    int sides = 0;
    for (std::size_t q = 0; q < pts.size(); ++q) {
      if (pts[q][n.axis] != p || leaf_of[q] < 0) continue;
      std::int32_t c = leaf_of[q], up = t.nodes[c].parent;
      for (int guard = 0; up >= 0 && up != static_cast<std::int32_t>(i) && guard < 64; ++guard) c = up, up = t.nodes[c].parent;
      if (up == static_cast<std::int32_t>(i)) sides |= c == n.children[0] ? 1 : 2;
    }
    v.planes += sides == 3;
  }
}

template <class Num> std::vector<std::array<Vec3<Num>, 3>> mesh_tris(const Mesh& m) {
  std::vector<std::array<Vec3<Num>, 3>> out;
  for (std::size_t i = 0; i < m.size(); ++i) out.push_back(m.triangle<Num>(i));
  return out;
}
template <class Num> KdTree<Num, 3> mesh_tree(const std::vector<std::array<Vec3<Num>, 3>>& tris) {
  std::vector<Box<Num, 3>> b;
  for (const auto& t : tris) b.push_back(triangle_bounds(t));
  NoProbe none;
  return kd_build<Num, 3>(b, false, none);
}

// A mesh with its tree prebuilt in every mode, for many rays. Filtered mode: the interval tree
// and walk, or the exact ones when an interval comparison is undecided (as the adapter does).
struct Scene {
  Mesh mesh;
  std::vector<std::array<Vec3<float>, 3>> tf;
  std::vector<std::array<Vec3<double>, 3>> td;
  std::vector<std::array<Vec3<Interval>, 3>> ti;
  std::vector<std::array<Vec3<Q>, 3>> tq;
  KdTree<float, 3> kf;
  KdTree<double, 3> kdd;
  std::optional<KdTree<Interval, 3>> ki;  // none if the interval build was undecided
  KdTree<Q, 3> kq;
  std::size_t fallbacks = 0;
  explicit Scene(Mesh m) : mesh(std::move(m)), tf(mesh_tris<float>(mesh)), td(mesh_tris<double>(mesh)), ti(mesh_tris<Interval>(mesh)), tq(mesh_tris<Q>(mesh)) {
    kf = mesh_tree(tf), kdd = mesh_tree(td), kq = mesh_tree(tq);
    try {
      ki = mesh_tree(ti);
    } catch (const Uncertain&) {
    }
  }
  template <class Num> static ray::Ray3<Num> ray_of(const RayIn& r) { return {vec_from<Num, 3>(r.o), vec_from<Num, 3>(r.d)}; }
  template <class Num> static HitOutput out(const KdHit<Num>& h) {
    HitOutput o = make_hit<Num>(h.hit, h.prim, h.t, h.b);
    o.nodes_visited = h.nodes_visited, o.prim_tests = h.prim_tests;
    return o;
  }
  HitOutput run(Numeric n, const RayIn& r) {
    NoProbe none;
    switch (n) {
      case Numeric::f32: return out(kd_traverse_tree<float>(kf, tf, ray_of<float>(r), none));
      case Numeric::f64: return out(kd_traverse_tree<double>(kdd, td, ray_of<double>(r), none));
      case Numeric::filtered:
        if (ki) {
          try {
            return out(kd_traverse_tree<Interval>(*ki, ti, ray_of<Interval>(r), none));
          } catch (const Uncertain&) {
          }
        }
        ++fallbacks;
        [[fallthrough]];
      default: return out(kd_traverse_tree<Q>(kq, tq, ray_of<Q>(r), none));
    }
  }
};

// The split planes of an exact tree: (axis, position).
template <int D> std::vector<std::pair<int, Q>> split_planes(const KdTree<Q, D>& t) {
  std::vector<std::pair<int, Q>> out;
  for (const auto& n : t.nodes)
    if (n.left >= 0) out.push_back({n.axis, n.split});
  return out;
}

inline double grid_coord(std::mt19937_64& rng, double lo, double hi, int bits) {
  std::uniform_real_distribution<double> u(lo, hi);
  return std::ldexp(std::round(std::ldexp(u(rng), bits)), -bits);
}

}  // namespace sw::testing::kd
