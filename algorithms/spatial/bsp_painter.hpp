// The painter's order from a BSP tree: for an eye, every node's far side first, then the node's own
// fragments, then its near side, so each fragment is painted after every fragment it hides.
// bsp-build runs as a nested listing. Semantics: docs/spatial/bsp.md.
#pragma once
#include <cstdint>
#include <string_view>
#include <vector>
#include "spatial/bsp_build.hpp"

namespace sw::spatial {

template <class Num> struct BspPaint {
  BspTree<Num> tree;
  std::vector<std::int32_t> order;  // fragment indices, back to front
};

struct BspPainter {
  static constexpr std::string_view id = "bsp-painter";
  static constexpr std::string_view summary = "Painter's order from a BSP tree: far side, the node's fragments, near side";
#define SW_LINES_BSP_PAINTER(X) \
  X(build, "T <- bsp-build(segments)") \
  X(root, "push visit(root)") \
  X(loop, "while the stack is not empty:") \
  X(visit, "    pop visit(N): s <- orient(N's line, eye)          -- s >= 0: the eye is in front (on the line: either way)") \
  X(push, "        push visit(near side), draw(N), visit(far side)  -- near = front if s >= 0; empty sides are skipped") \
  X(plot, "    pop draw(N): paint N's fragments                  -- in the node's order") \
  X(done, "done: the fragments back to front")
  SW_LISTING("BSP painter's order", SW_LINES_BSP_PAINTER)
#undef SW_LINES_BSP_PAINTER
};

template <NumberType Num, StepProbe Probe = NoProbe>
BspPaint<Num> bsp_painter(const std::vector<Segment2<Num>>& segs, const Vec2<Num>& eye, std::size_t max_fragments, Probe& probe) {
  using L = BspPainter;
  BspPaint<Num> out;
  if constexpr (Probe::on) {
    auto& s = probe.step(L::build, StepKind::init).idx("n", static_cast<std::int64_t>(segs.size()));
    s.point(eye).label("eye").keep();
    for (std::size_t i = 0; i < segs.size(); ++i)
      s.segment(segs[i].a, segs[i].b).label("seg").value(Num(static_cast<std::int64_t>(i))).keep();
  }
  {
    const auto call = nested<BspBuild>(probe);
    out.tree = bsp_build<Num>(segs, max_fragments, probe);
  }
  if (out.tree.exhausted) return out;
  const BspTree<Num>& t = out.tree;
  // Tasks: v >= 0 visits node v; v < 0 draws node -v - 1's fragments.
  std::vector<std::int32_t> stack{0};
  if constexpr (Probe::on) probe.step(L::root, StepKind::init).idx("node", 0).idx("stack", 1);
  // Each node is pushed once as a visit and once as a draw: at most 2 * nodes passes.
  while (!stack.empty()) {
    const std::int32_t task = stack.back();
    stack.pop_back();
    if (task < 0) {
      const std::int32_t id = -task - 1;
      for (const std::int32_t f : t.nodes[id].frags) {  // bounded: the node's fragments
        out.order.push_back(f);
        if constexpr (Probe::on)
          probe.step(L::plot, StepKind::plot)
              .idx("node", id)
              .idx("frag", f)
              .idx("seg", t.frags[f].seg)
              .idx("k", static_cast<std::int64_t>(out.order.size()) - 1)
              .segment(t.frags[f].a, t.frags[f].b)
              .label("k")
              .value(Num(static_cast<std::int64_t>(out.order.size()) - 1))
              .keep();
      }
      continue;
    }
    const BspNode& n = t.nodes[task];
    const Segment2<Num>& line = segs[n.splitter];
    const Num s = orient2(line.a, line.b, eye);
    const bool in_front = !(s < Num(0));
    const std::int32_t near = in_front ? n.front : n.back, far = in_front ? n.back : n.front;
    if constexpr (Probe::on) {
      const auto across = bsp_line_across(line, t.boxes[0]);
      probe.step(L::visit, StepKind::decide)
          .idx("node", task)
          .idx("seg", n.splitter)
          .num("s", s)
          .idx("in_front", in_front)
          .node(task, n.parent, t.boxes[task].lo, t.boxes[task].hi)
          .segment(across[0], across[1])
          .label("splitter")
          .value(s);
    }
    if (near >= 0) stack.push_back(near);
    stack.push_back(-task - 1);
    if (far >= 0) stack.push_back(far);
    if constexpr (Probe::on)
      probe.step(L::push, StepKind::advance)
          .idx("near", near)
          .idx("far", far)
          .idx("stack", static_cast<std::int64_t>(stack.size()));
  }
  if constexpr (Probe::on) probe.step(L::done, StepKind::done).idx("painted", static_cast<std::int64_t>(out.order.size()));
  return out;
}

}  // namespace sw::spatial
