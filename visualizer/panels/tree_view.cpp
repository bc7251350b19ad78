#include "panels/tree_view.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include "panels/theme.hpp"

namespace sw::vis {

std::optional<std::size_t> TreeDiagram::find(std::int64_t id) const {
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (nodes[i].id == id) return i;
  return std::nullopt;
}

namespace {

bool is_node(GeoKind k) { return k == GeoKind::node2 || k == GeoKind::node3; }

// Node ids to diagram indices; ids are small non-negative integers in practice, so a flat table.
struct IdIndex {
  std::vector<std::int32_t> at;
  std::int32_t get(std::int64_t id) const { return id >= 0 && id < std::int64_t(at.size()) ? at[std::size_t(id)] : -1; }
  void set(std::int64_t id, std::int32_t i) {
    if (id < 0 || id > (std::int64_t{1} << 24)) return;  // beyond any tree a trace can hold
    if (std::size_t(id) >= at.size()) at.resize(std::size_t(id) + 1, -1);
    at[std::size_t(id)] = i;
  }
};

}  // namespace

TreeDiagram build_tree_diagram(const TraceModel& m, std::size_t through) {
  TreeDiagram d;
  const TraceView& t = m.trace();
  IdIndex index;
  std::vector<std::int64_t> parent_id;
  for (std::size_t s = 0; s < t.size() && s <= through; ++s) {
    const StepRecord& st = t.at(s);
    for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g) {
      const GeoRecord& geo = t.geo_at(g);
      if (!is_node(geo.kind)) continue;
      const auto id = static_cast<std::int64_t>(t.geo_double(geo, 0));
      if (index.get(id) >= 0) continue;
      index.set(id, static_cast<std::int32_t>(d.nodes.size()));
      d.nodes.push_back({id, -1, {}, static_cast<std::uint32_t>(s), 0, 0});
      parent_id.push_back(static_cast<std::int64_t>(t.geo_double(geo, 1)));
    }
  }
  for (std::size_t i = 0; i < d.nodes.size(); ++i) {
    const std::int32_t p = index.get(parent_id[i]);
    if (p >= 0 && std::size_t(p) != i) d.nodes[i].parent = p, d.nodes[std::size_t(p)].children.push_back(std::int32_t(i));
  }
  // Layout without recursion: depth-first order by an explicit stack, leaves in slots, then
  // parents over their children in reverse order.
  std::vector<std::size_t> order, stack;
  for (std::size_t i = d.nodes.size(); i-- > 0;)
    if (d.nodes[i].parent < 0) stack.push_back(i);
  std::vector<char> seen(d.nodes.size(), 0);
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    if (seen[i]) continue;  // a malformed trace's cycle
    seen[i] = 1;
    order.push_back(i);
    const auto& ch = d.nodes[i].children;
    for (auto c = ch.rbegin(); c != ch.rend(); ++c) {
      d.nodes[std::size_t(*c)].y = d.nodes[i].y + 1;
      stack.push_back(std::size_t(*c));
    }
  }
  for (std::size_t i : order)
    if (d.nodes[i].children.empty()) d.nodes[i].x = d.width++;
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    TreeDiagram::Node& n = d.nodes[*it];
    d.depth = std::max(d.depth, int(n.y));
    if (!n.children.empty()) n.x = (d.nodes[std::size_t(n.children.front())].x + d.nodes[std::size_t(n.children.back())].x) / 2;
  }
  return d;
}

TreeMarks tree_marks(const TraceModel& m, const TreeDiagram& d, std::size_t step) {
  TreeMarks k;
  const TraceView& t = m.trace();
  for (const auto& n : d.nodes) k.built += n.first_step <= step;
  if (step >= t.size()) return k;
  // The current node: the node items of the step itself, or of the nearest earlier step of the
  // algorithm's own listing that names one (a leaf's tests and nested calls keep it current).
  for (std::size_t s = step + 1, bound = 0; s-- > 0 && bound < 4096 && k.current.empty(); ++bound) {
    const StepRecord& st = t.at(s);
    if (st.scope != 0) continue;
    for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g) {
      const GeoRecord& geo = t.geo_at(g);
      if (!is_node(geo.kind)) continue;
      if (auto i = d.find(static_cast<std::int64_t>(t.geo_double(geo, 0)))) k.current.push_back(*i);
    }
  }
  for (const VarState& v : m.state_at(step)) {
    if (v.name != "stack" || v.shape != VarShape::list) continue;
    // The list's text is "[a, b, ...]": parse the ids back.
    const char* p = v.text.c_str();
    while (*p) {
      char* end = nullptr;
      const long long id = std::strtoll(p, &end, 10);
      if (end == p) {
        ++p;
        continue;
      }
      if (auto i = d.find(id)) k.stack.push_back(*i);
      p = end;
    }
  }
  if (!k.current.empty())
    for (std::int32_t i = std::int32_t(k.current.front()), bound = 0; i >= 0 && bound < 4096; i = d.nodes[std::size_t(i)].parent, ++bound)
      k.path.push_back(std::size_t(i));
  return k;
}

void TreeCanvas::follow(const Canvas& other) {
  if (const auto* o = dynamic_cast<const TreeCanvas*>(&other)) scale_ = o->scale_, row_ = o->row_, pan_x_ = o->pan_x_, pan_y_ = o->pan_y_, fit_pending_ = false;
}

std::optional<std::array<float, 2>> TreeCanvas::node_centre(std::size_t node) const {
  if (node >= drawn_.size() || std::isnan(drawn_[node][0])) return std::nullopt;
  return drawn_[node];
}

CanvasEvents TreeCanvas::draw(const CanvasInput& in, ImVec2 size) {
  CanvasEvents ev;
  if (!in.model) return ev;
  // Quiz mode lays out the tree built so far, refitted as it grows; otherwise the whole tree, once.
  const std::size_t through = in.hide_future ? in.step : SIZE_MAX;
  if (in.model != model_ || through != through_) {
    const std::size_t before = diagram_.nodes.size();
    const bool fresh = in.model != model_;
    model_ = in.model, through_ = through, diagram_ = build_tree_diagram(*model_, through);
    if (fresh || diagram_.nodes.size() != before) fit_pending_ = true;
  }
  const TreeDiagram& d = diagram_;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  origin_ = {origin.x, origin.y}, size_ = {size.x, size.y};
  ImGui::InvisibleButton("##tree", size, ImGuiButtonFlags_MouseButtonLeft);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  dl->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), theme::kCanvasBg);
  constexpr float kMargin = 28, kLegend = 20, kLevel = 1.6f;  // kLevel: rows 1.6 slots apart, when they fit
  if (fit_pending_ && size.x > 2 * kMargin && size.y > 2 * kMargin) {
    const float w = std::max(d.width - 1, 1.f), h = std::max(float(d.depth), 1.f), room_y = size.y - 2 * kMargin - kLegend;
    scale_ = std::clamp(std::min((size.x - 2 * kMargin) / w, room_y / (kLevel * h)), 0.01f, 120.f);
    row_ = std::max(kLevel * scale_, std::min(room_y / h, 48.f));
    pan_x_ = (size.x - scale_ * (d.width - 1)) / 2, pan_y_ = kMargin;
    fit_pending_ = false;
  }
  const TreeMarks marks = tree_marks(*model_, d, in.step);
  if (focus_pending_ && !marks.current.empty()) {
    const auto& n = d.nodes[marks.current.front()];
    const float sx = pan_x_ + scale_ * n.x, sy = pan_y_ + row_ * n.y;
    if (sx < kMargin || sx > size.x - kMargin || sy < kMargin || sy > size.y - kMargin)
      pan_x_ = size.x / 2 - scale_ * n.x, pan_y_ = size.y / 2 - row_ * n.y;
    focus_pending_ = false;
  }
  if (hovered && ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
    const ImVec2 dd = ImGui::GetIO().MouseDelta;
    pan_x_ += dd.x, pan_y_ += dd.y;
  }
  if (hovered && ImGui::GetIO().MouseWheel != 0) {
    const ImVec2 mp = ImGui::GetIO().MousePos;
    const float f = std::pow(1.15f, ImGui::GetIO().MouseWheel), mx = mp.x - origin.x, my = mp.y - origin.y;
    const float s = std::clamp(scale_ * f, 0.01f, 400.f), g = s / scale_;
    pan_x_ = mx - (mx - pan_x_) * g, pan_y_ = my - (my - pan_y_) * g;
    scale_ = s, row_ *= g;
  }
  auto at = [&](const TreeDiagram::Node& n) { return ImVec2(origin.x + pan_x_ + scale_ * n.x, origin.y + pan_y_ + row_ * n.y); };
  const ImVec2 lo = origin, hi(origin.x + size.x, origin.y + size.y);
  auto outside = [&](ImVec2 a, ImVec2 b) { return std::max(a.x, b.x) < lo.x || std::min(a.x, b.x) > hi.x || std::max(a.y, b.y) < lo.y || std::min(a.y, b.y) > hi.y; };
  std::vector<char> mark(d.nodes.size(), 0);  // 1 path, 2 stack, 3 current
  for (std::size_t i : marks.path) mark[i] = 1;
  for (std::size_t i : marks.stack) mark[i] = 2;
  for (std::size_t i : marks.current) mark[i] = 3;
  const float r = std::clamp(scale_ * 0.3f, 1.5f, 11.f);
  for (std::size_t i = 0; i < d.nodes.size(); ++i) {  // edges first
    const auto& n = d.nodes[i];
    if (n.first_step > in.step || n.parent < 0) continue;
    const bool on_path = mark[i] == 3 || mark[i] == 1;
    const ImVec2 a = at(d.nodes[std::size_t(n.parent)]), b = at(n);
    if (!outside(a, b)) dl->AddLine(a, b, on_path ? theme::kQ : theme::kGrid, on_path ? 2.5f : 1.2f);
  }
  drawn_.assign(d.nodes.size(), {NAN, NAN});
  std::optional<std::size_t> hover_node;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  for (std::size_t i = 0; i < d.nodes.size(); ++i) {
    const auto& n = d.nodes[i];
    if (n.first_step > in.step) continue;
    const ImVec2 p = at(n);
    if (p.x < origin.x - r || p.x > origin.x + size.x + r || p.y < origin.y - r || p.y > origin.y + size.y + r) continue;
    drawn_[i] = {p.x, p.y};
    const ImU32 fill = mark[i] == 3 ? theme::kCurrentPixel : mark[i] == 2 ? theme::kHandleP0 : mark[i] == 1 ? theme::kQ
                       : n.children.empty() && !in.hide_future ? theme::kCentre : theme::kGridAxis;  // quiz: no leaf yet
    if (r < 3 && !mark[i]) dl->AddRectFilled(ImVec2(p.x - r, p.y - r), ImVec2(p.x + r, p.y + r), fill);  // thousands: cheap squares
    else dl->AddCircleFilled(p, std::max(r, 3.f), fill, 16);
    if (n.first_step == in.step) dl->AddCircle(p, r + 3, theme::kHandleP1, 16, 2);
    if (scale_ >= 22) {
      char id[24];
      std::snprintf(id, sizeof id, "%lld", static_cast<long long>(n.id));
      dl->AddText(ImVec2(p.x + r + 2, p.y - r - 2), theme::kLabel, id);
    }
    if (hovered && std::hypot(mouse.x - p.x, mouse.y - p.y) <= r + 3) hover_node = i;
  }
  if (hover_node) {
    const auto& n = d.nodes[*hover_node];
    ImGui::SetTooltip("node %lld%s, depth %d, created at step %u\nclick: go to that step", static_cast<long long>(n.id),
                      n.children.empty() && !in.hide_future ? " (leaf)" : "", int(n.y), n.first_step);
    const ImGuiIO& io = ImGui::GetIO();
    const bool dragged = io.MouseDragMaxDistanceSqr[0] > io.MouseDragThreshold * io.MouseDragThreshold;
    if (ImGui::IsMouseReleased(ImGuiMouseButton_Left) && !dragged) ev.jump_to = n.first_step;
  }
  char legend[160];
  if (in.hide_future)  // the quiz's diagram holds only the nodes built so far
    std::snprintf(legend, sizeof legend, "%zu nodes built so far%s", marks.built, marks.stack.empty() ? "" : "; green: on the stack");
  else
    std::snprintf(legend, sizeof legend, "%zu of %zu nodes built; depth %d%s", marks.built, d.nodes.size(), d.depth,
                  marks.stack.empty() ? "" : "; green: on the stack");
  dl->AddText(ImVec2(origin.x + 8, origin.y + size.y - ImGui::GetFontSize() - 5), theme::kLabel, d.nodes.empty() ? "this trace records no tree nodes" : legend);
  corner_label(dl, origin, size, in.label);
  dl->PopClipRect();
  return ev;
}

}  // namespace sw::vis
