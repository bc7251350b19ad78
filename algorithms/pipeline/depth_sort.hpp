// The painter's algorithm by depth sort (Newell, Newell and Sancha): window-space triangles sorted
// farthest first, each pair whose extents overlap put in order by cheap tests before costly ones,
// and a polygon split by another's plane where no order exists (penetration, cyclic overlap). Depth
// z grows away from the eye; depth at (x, y) is the parent triangle's plane, as the z-buffer's.
// Painting uses triangle-edge's samples and tie rule, which cover two polygons with disjoint
// interiors at disjoint samples; so the painted image is the z-buffer's wherever one surface is
// nearest (docs/pipeline/semantics.md).
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <string_view>
#include <vector>
#include "core/probe.hpp"
#include "pipeline/depth_plane.hpp"

namespace sw::pipe {

inline constexpr std::int64_t kTie = -2;  // a pixel where two surfaces are nearest at the same depth

template <class Num> struct SortPolygon {
  std::vector<Vec3<Num>> v;  // convex, in its parent triangle's order
  DepthPlane<Num> plane;     // the parent triangle's
  std::int64_t id = 0;
  bool moved = false;        // moved to the front once: moving it again may close a cycle
};

struct PaintedImage {
  std::int64_t width = 0, height = 0;
  std::vector<std::int64_t> id;  // -1: nothing painted; kTie
  std::int64_t painted = 0, moves = 0, splits = 0, ties = 0;
  std::int64_t tests = 0;        // pairs (P, Q) whose depth ranges overlap, compared
  std::int64_t wrong = 0;        // samples where a farther surface was painted over a nearer one
  bool gave_up = false;          // a bound was reached: the rest painted in list order
};

struct DepthSort {
  static constexpr std::string_view id = "depth-sort";
  static constexpr std::string_view summary = "Painter's algorithm: Newell-Newell-Sancha depth sort, splitting on penetration and cycles";
#define SW_LINES_DEPTH_SORT(X) \
  X(sort, "sort the triangles by their farthest depth, farthest first (depth grows away from the eye)") \
  X(pick, "P <- the first polygon of the list") \
  X(each, "for each other Q whose depth range overlaps P's (Q's farthest > P's nearest):") \
  X(extent, "    if their x ranges or their y ranges do not overlap: next Q") \
  X(behind, "    if every vertex of P is on or behind Q's plane: next Q") \
  X(front, "    if every vertex of Q is on or in front of P's plane: next Q") \
  X(overlap, "    if the projections' interiors do not overlap: next Q") \
  X(move, "    if Q is on or behind P's plane, or P on or in front of Q's, and (Q was never moved or no cut exists): mark Q, move it to the front, go to pick") \
  X(split, "    else cut P by Q's plane, else Q by P's, whichever the plane crosses (else by an edge line); the pieces replace it; go to pick") \
  X(paint, "paint P: each sample it covers takes its id, a tie where the surface there has the same depth; remove P") \
  X(done, "done")
  SW_LISTING("Painter's algorithm (depth sort)", SW_LINES_DEPTH_SORT)
#undef SW_LINES_DEPTH_SORT
};

namespace depth_sort_detail {

// s(v) for a cut: z - plane depth (> 0: v behind the plane), or a 2D edge function.
template <class Num> struct Cut {
  Num a, b, c, d;  // s = a x + b y + c z + d
  Num at(const Vec3<Num>& v) const { return Num(a * v.x + b * v.y + c * v.z + d); }
};
template <class Num> Cut<Num> plane_cut(const DepthPlane<Num>& p) {
  return {Num(-p.zx), Num(-p.zy), Num(1), Num(p.zx * p.a.x + p.zy * p.a.y - p.a.z)};
}
// The vertical plane through the line p -> q: positive on its left.
template <class Num> Cut<Num> edge_cut(const Vec3<Num>& p, const Vec3<Num>& q) {
  return {Num(p.y - q.y), Num(q.x - p.x), Num(0), Num(p.x * q.y - p.y * q.x)};
}

// Which sides of a cut the polygon's vertices lie on: {some s < 0, some s > 0}.
template <class Num> std::array<bool, 2> sides(const SortPolygon<Num>& P, const Cut<Num>& cut) {
  std::array<bool, 2> out{false, false};
  for (const Vec3<Num>& v : P.v) {
    const Num s = cut.at(v);
    out[0] = out[0] || s < Num(0), out[1] = out[1] || s > Num(0);
  }
  return out;
}

template <class Num> std::array<Num, 2> range(const SortPolygon<Num>& P, int axis) {
  std::array<Num, 2> r{P.v[0][axis], P.v[0][axis]};
  for (const Vec3<Num>& v : P.v) r = {std::min(r[0], v[axis]), std::max(r[1], v[axis])};
  return r;
}

// Separating axes: the interiors are disjoint when an edge line of one has the other wholly on its
// closed outer side. Both convex, with nonzero area.
template <class Num> bool interiors_overlap(const SortPolygon<Num>& P, const SortPolygon<Num>& Q) {
  for (int pass = 0; pass < 2; ++pass) {
    const SortPolygon<Num>&A = pass ? Q : P, &B = pass ? P : Q;
    const Num turn = A.plane.area2 > Num(0) ? Num(1) : Num(-1);  // inside on the left when counter-clockwise
    for (std::size_t k = 0; k < A.v.size(); ++k) {
      const Cut<Num> e = edge_cut(A.v[k], A.v[(k + 1) % A.v.size()]);
      bool outside = true;
      for (const Vec3<Num>& v : B.v) outside = outside && e.at(v) * turn <= Num(0);
      if (outside) return false;
    }
  }
  return true;
}

// The pieces of P on each side of the cut; vertices on it go to both. Precondition: the cut crosses P.
template <class Num> std::array<SortPolygon<Num>, 2> split(const SortPolygon<Num>& P, const Cut<Num>& cut) {
  std::array<SortPolygon<Num>, 2> out{SortPolygon<Num>{{}, P.plane, P.id}, SortPolygon<Num>{{}, P.plane, P.id}};
  for (std::size_t k = 0; k < P.v.size(); ++k) {
    const Vec3<Num>&p = P.v[k], &q = P.v[(k + 1) % P.v.size()];
    const Num sp = cut.at(p), sq = cut.at(q);
    if (sp <= Num(0)) out[0].v.push_back(p);
    if (sp >= Num(0)) out[1].v.push_back(p);
    if ((sp < Num(0) && sq > Num(0)) || (sp > Num(0) && sq < Num(0))) {
      const Num t = sp / (sp - sq);
      const Vec3<Num> x{Num(p.x + t * (q.x - p.x)), Num(p.y + t * (q.y - p.y)), Num(p.z + t * (q.z - p.z))};
      out[0].v.push_back(x), out[1].v.push_back(x);
    }
  }
  return out;
}

// How to break P's order with Q (Q must come first, or they penetrate): {cut P?, the cut}. Q's
// plane where it crosses P (P has vertices strictly on both sides), else P's where it crosses Q;
// in a cycle of polygons each wholly on one side of the other's plane, an edge line of one that
// crosses the other. None: the projections coincide.
template <class Num> std::optional<std::pair<bool, Cut<Num>>> choose_cut(const SortPolygon<Num>& P, const SortPolygon<Num>& Q) {
  auto crosses = [](const SortPolygon<Num>& A, const Cut<Num>& c) { const auto s = sides(A, c); return s[0] && s[1]; };
  if (crosses(P, plane_cut(Q.plane))) return std::pair{true, plane_cut(Q.plane)};
  if (crosses(Q, plane_cut(P.plane))) return std::pair{false, plane_cut(P.plane)};
  for (int pass = 0; pass < 2; ++pass) {
    const SortPolygon<Num>&A = pass ? Q : P, &B = pass ? P : Q;
    for (std::size_t e = 0; e < A.v.size(); ++e)
      if (const Cut<Num> c = edge_cut(A.v[e], A.v[(e + 1) % A.v.size()]); crosses(B, c)) return std::pair{pass == 1, c};
  }
  return std::nullopt;
}

template <class Num> std::vector<Vec2<Num>> flat(const SortPolygon<Num>& P) {
  std::vector<Vec2<Num>> out;
  for (const Vec3<Num>& v : P.v) out.push_back({v.x, v.y});
  return out;
}

// The samples of the window P covers: triangle-edge's on each triangle of a fan, which share edges inside P.
template <class Num> std::vector<Pixel> polygon_samples(const SortPolygon<Num>& P, std::int64_t width, std::int64_t height) {
  std::vector<Pixel> out;
  for (std::size_t k = 1; k + 1 < P.v.size(); ++k) {
    const std::vector<Pixel> part = covered_samples(std::array<Vec3<Num>, 3>{P.v[0], P.v[k], P.v[k + 1]}, width, height);
    out.insert(out.end(), part.begin(), part.end());
  }
  return out;
}

}  // namespace depth_sort_detail

// max_tests bounds the pairs compared, and so the steps: every move and cut follows a test, and
// each round paints, moves or cuts. max_splits bounds the list, and so each round's scan of it.
// Reaching either sets gave_up. Ids are expected distinct.
template <NumberType Num, StepProbe Probe = NoProbe>
PaintedImage depth_sort(std::int64_t width, std::int64_t height, const std::vector<std::array<Vec3<Num>, 3>>& tris,
                        const std::vector<std::int64_t>& ids, std::int64_t max_tests, std::int64_t max_splits, Probe& probe) {
  using L = DepthSort;
  using namespace depth_sort_detail;
  PaintedImage img{width, height, std::vector<std::int64_t>(width * height, -1)};
  std::vector<DepthPlane<Num>> planes;                 // of the painted polygons
  std::vector<std::int32_t> shown(width * height, -1);  // the painted plane at each sample
  std::vector<SortPolygon<Num>> list;
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const DepthPlane<Num> plane = depth_plane(tris[t]);
    if (plane.area2 == Num(0)) {  // edge-on: covers no sample
      if constexpr (Probe::on) probe.step(L::sort, StepKind::miss).idx("t", ids[t]).num("area2", plane.area2);
      continue;
    }
    list.push_back({{tris[t][0], tris[t][1], tris[t][2]}, plane, ids[t]});
  }
  auto farthest = [](const SortPolygon<Num>& P) { return range(P, 2)[1]; };
  auto by_farthest = [&](const SortPolygon<Num>& a, const SortPolygon<Num>& b) { return farthest(a) > farthest(b); };
  std::stable_sort(list.begin(), list.end(), by_farthest);
  if constexpr (Probe::on) probe.step(L::sort, StepKind::init).idx("polygons", std::int64_t(list.size()));
  // Each round paints one polygon, or compares at least one pair and moves or cuts one.
  while (!list.empty()) {
    const SortPolygon<Num>& P = list.front();
    if constexpr (Probe::on) probe.step(L::pick, StepKind::init).idx("P", P.id).idx("vertices", std::int64_t(P.v.size())).geo_list(GeoKind::polygon, std::span<const Vec2<Num>>(flat(P))).label("P").replace();
    std::size_t blocker = 0;  // the Q that P may hide, if any
    bool q_first = false;     // whether that Q may simply be painted first
    const auto px = range(P, 0), py = range(P, 1), pz = range(P, 2);
    for (std::size_t k = 1; k < list.size() && !img.gave_up; ++k) {
      const SortPolygon<Num>& Q = list[k];
      const auto qz = range(Q, 2);
      if (!(qz[1] > pz[0])) continue;
      if (img.tests == max_tests) {
        img.gave_up = true;
        break;
      }
      ++img.tests;
      if constexpr (Probe::on) probe.step(L::each, StepKind::advance).idx("Q", Q.id).num("P.near", pz[0]).num("Q.far", qz[1]).geo_list(GeoKind::polygon, std::span<const Vec2<Num>>(flat(Q))).label("Q").replace();
      const auto qx = range(Q, 0), qy = range(Q, 1);
      const bool apart = px[1] <= qx[0] || qx[1] <= px[0] || py[1] <= qy[0] || qy[1] <= py[0];
      if constexpr (Probe::on) probe.step(L::extent, StepKind::decide).idx("apart", apart);
      if (apart) continue;
      const auto p_by_q = sides(P, plane_cut(Q.plane)), q_by_p = sides(Q, plane_cut(P.plane));
      if constexpr (Probe::on) probe.step(L::behind, StepKind::decide).idx("P.in_front", p_by_q[0]).idx("P.behind", p_by_q[1]);
      if (!p_by_q[0]) continue;
      if constexpr (Probe::on) probe.step(L::front, StepKind::decide).idx("Q.in_front", q_by_p[0]).idx("Q.behind", q_by_p[1]);
      if (!q_by_p[1]) continue;
      const bool overlap = interiors_overlap(P, Q);
      if constexpr (Probe::on) probe.step(L::overlap, StepKind::decide).idx("overlap", overlap);
      if (!overlap) continue;
      blocker = k, q_first = !q_by_p[0] || !p_by_q[1];
      break;
    }
    if (blocker != 0) {
      const SortPolygon<Num>& Q = list[blocker];
      // A second move may close a cycle: cut instead where a cut exists (pieces of two
      // polygons cut by each other's planes can share their projection, and no cut parts them).
      const auto choice = q_first && !Q.moved ? std::nullopt : choose_cut(P, Q);
      const bool move = q_first && (!choice || !Q.moved);
      if constexpr (Probe::on) probe.step(L::move, StepKind::decide).idx("q_first", q_first).idx("moved_before", Q.moved).idx("can_cut", choice.has_value()).idx("move", move);
      if (move) {
        SortPolygon<Num> q = Q;
        q.moved = true;
        list.erase(list.begin() + blocker);
        list.insert(list.begin(), std::move(q));
        ++img.moves;
        continue;
      }
      if (choice && img.splits < max_splits) {
        const std::size_t cut_index = choice->first ? 0 : blocker;
        const SortPolygon<Num> whole = list[cut_index];
        const auto pieces = split(whole, choice->second);
        if constexpr (Probe::on)
          probe.step(L::split, StepKind::advance).idx("cut", whole.id).idx("by", list[cut_index == 0 ? blocker : 0].id)
              .geo_list(GeoKind::polygon, std::span<const Vec2<Num>>(flat(pieces[0]))).geo_list(GeoKind::polygon, std::span<const Vec2<Num>>(flat(pieces[1])));
        // The pieces take the whole's place, the farther first; the list keeps its other moves.
        list.erase(list.begin() + cut_index);
        const bool swap = farthest(pieces[1]) > farthest(pieces[0]);
        for (int k = 1; k >= 0; --k)
          if (const auto& piece = pieces[k ^ swap]; piece.v.size() >= 3) list.insert(list.begin() + cut_index, piece);
        ++img.splits;
        continue;
      }
    }
    img.gave_up = img.gave_up || blocker != 0;
    planes.push_back(P.plane);
    // Paint P. A sample already painted holds the surface P now covers: farther, equal (a tie) or,
    // when the order is wrong, nearer.
    for (const Pixel& s : polygon_samples(P, width, height)) {
      const std::size_t at = s.y * width + s.x;
      const Num z = P.plane.at(Num(s.x), Num(s.y));
      const bool painted = shown[at] >= 0;
      const Num under = painted ? planes[shown[at]].at(Num(s.x), Num(s.y)) : z;
      const bool tie = painted && under == z;
      img.wrong += painted && under < z;
      img.id[at] = tie ? kTie : P.id;
      shown[at] = static_cast<std::int32_t>(planes.size() - 1);
      if constexpr (Probe::on) probe.step(L::paint, StepKind::plot).idx("id", P.id).num("z", z).idx("tie", tie).pixel(s).value(Num(P.id)).keep();
    }
    ++img.painted;
    list.erase(list.begin());
  }
  for (std::int64_t v : img.id) img.ties += v == kTie;
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("painted", img.painted).idx("splits", img.splits).idx("tests", img.tests).idx("ties", img.ties);
  return img;
}

}  // namespace sw::pipe
