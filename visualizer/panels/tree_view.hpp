// The tree view: the nodes a build records (node and node3 geometry: id, parent, bounds) drawn as
// a diagram, root on top. Nodes appear at the step that creates them; the current step's nodes
// are highlighted, and so are the nodes of a recorded "stack" list variable (a traversal's
// pending nodes) and the path from the root to the current node. Clicking a node goes to the
// step that created it. Drag to pan, wheel to zoom.
#pragma once
#include <cstdint>
#include <cstddef>
#include <optional>
#include <vector>
#include "panels/canvas.hpp"

namespace sw::vis {

struct TreeDiagram {
  struct Node {
    std::int64_t id = 0;
    std::int32_t parent = -1;          // index into nodes, -1 for a root
    std::vector<std::int32_t> children;
    std::uint32_t first_step = 0;      // the step that first records it
    float x = 0, y = 0;                // layout: x in leaf slots, y = depth
  };
  std::vector<Node> nodes;             // in order of first appearance
  float width = 0;                     // leaf slots used
  int depth = 0;
  std::optional<std::size_t> find(std::int64_t id) const;
};

// The diagram of every node the trace records at any depth (a query sees the tree its nested build
// records; a node recorded again keeps its first step), in steps up to `through` (all by default:
// quiz mode lays out only the tree built so far, whose shape must not tell what comes).
// Leaves take consecutive slots; a parent sits over the middle of its children.
TreeDiagram build_tree_diagram(const TraceModel& m, std::size_t through = SIZE_MAX);

// What the view marks at a step: the nodes its own geometry names, the stack variable's nodes and
// the path from the root to the first current node (indices into TreeDiagram::nodes).
struct TreeMarks {
  std::vector<std::size_t> current, stack, path;
  std::size_t built = 0;  // nodes whose first step is <= step
};
TreeMarks tree_marks(const TraceModel& m, const TreeDiagram& d, std::size_t step);

class TreeCanvas final : public Canvas {
 public:
  CanvasEvents draw(const CanvasInput& in, ImVec2 size) override;
  void fit() override { fit_pending_ = true; }
  void focus(const TraceModel&, std::size_t, double) override { focus_pending_ = true; }
  void follow(const Canvas& other) override;
  // Test hooks: the diagram of the last drawn model, and a node's screen centre in the last frame.
  const TreeDiagram& diagram() const { return diagram_; }
  std::optional<std::array<float, 2>> node_centre(std::size_t node) const;
  std::array<float, 4> canvas_rect() const { return {origin_[0], origin_[1], origin_[0] + size_[0], origin_[1] + size_[1]}; }

 private:
  std::shared_ptr<const TraceModel> model_;
  std::size_t through_ = SIZE_MAX;  // the last step the diagram holds
  TreeDiagram diagram_;
  // screen = origin + pan + (scale * x, row * y): a wide tree fits by narrowing its slots, not its rows.
  float scale_ = 40, row_ = 64, pan_x_ = 0, pan_y_ = 0;
  bool fit_pending_ = true, focus_pending_ = false;
  std::vector<std::array<float, 2>> drawn_;
  std::array<float, 2> origin_{}, size_{};
};

}  // namespace sw::vis
