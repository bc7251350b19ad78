// A quiz never shows what it asks: at a waiting question every view (plane, 3D, tree, image, lobe,
// table, plot, scene), the State panel and the listing draw exactly the frame of the question's
// shown step, and something of the question's own step appears only once it is answered. The
// question and its answer buttons are in view at 1024x640, wrapped inside the narration panel
// instead of running off its edge.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <imgui_internal.h>
#include <cmath>
#include "headless/headless.hpp"
#include "panels/tree_view.hpp"
#include "source_paths.hpp"

using namespace sw;
using namespace sw::vis;
using sw::testing::kLessons;

namespace {

constexpr int kW = 1024, kH = 640;

// The RGBA rows of one panel's rectangle in the last render.
std::vector<std::uint8_t> crop(const std::vector<std::uint8_t>& frame, const PanelRect& r) {
  std::vector<std::uint8_t> out;
  const int x0 = std::max(0, int(std::ceil(r.pos.x))), x1 = std::min(kW, int(r.right()));
  const int y0 = std::max(0, int(std::ceil(r.pos.y))), y1 = std::min(kH, int(r.bottom()));
  for (int y = y0; y < y1; ++y)
    out.insert(out.end(), frame.begin() + (std::ptrdiff_t(y) * kW + x0) * 4, frame.begin() + (std::ptrdiff_t(y) * kW + x1) * 4);
  return out;
}

struct Frame {
  std::vector<std::uint8_t> canvas, state, listing;
};

// Pixels that differ between two crops of one rectangle.
std::size_t differing(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  if (a.size() != b.size()) return a.size() + b.size();
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); i += 4) n += !std::equal(a.begin() + std::ptrdiff_t(i), a.begin() + std::ptrdiff_t(i + 4), b.begin() + std::ptrdiff_t(i));
  return n;
}
std::size_t differing(const Frame& a, const Frame& b) { return differing(a.canvas, b.canvas) + differing(a.state, b.state) + differing(a.listing, b.listing); }

Frame capture(HeadlessHost& host) {
  const std::vector<std::uint8_t>& f = host.render(3);
  const PanelLayout& l = host.app().layout();
  return {crop(f, l.canvas), crop(f, l.state), crop(f, l.listing)};
}

// Steps toward `target`, answering each question the gate stops at with its truth; the question
// waiting at `target`.
const Question* reach(Session& s, std::size_t target) {
  for (int guard = 0; guard < 64; ++guard) {
    s.set_step(target);
    if (s.step() == target) return s.quiz_pending();
    const Question* q = s.quiz_pending();
    if (!q) return nullptr;
    s.answer(q->answer);
  }
  return nullptr;
}

struct GateCase {
  const char* lesson;
  View view;
  std::size_t step;  // a question of the lesson's quiz; not its last (the sweep views wait for that)
};

}  // namespace

TEST_CASE("visualizer quiz gate: at a question every view shows its shown step, and the step itself only once answered", "[visualizer][quiz][render]") {
  const GateCase cases[] = {
      {"03-bresenham.md", View::plane2d, 6},          // branch: minor_step or major_step
      {"24-glass-tir.md", View::orbit3d, 156},         // flag tir
      {"16-kd-sah.md", View::tree, 63},                // sign cost vs 1200: node 2 is popped there
      {"20-minnaert-moon.md", View::image, 1},         // branch: powers or below
      {"22-phong-blinn.md", View::lobe, 2},            // flag front
      {"08-forward-difference-drift.md", View::table, 221},  // diverge
      {"08-forward-difference-drift.md", View::plot, 221},
      {"23-shadow-acne.md", View::scene, 21},          // flag blocked
  };
  for (const GateCase& c : cases) {
    INFO(c.lesson << ", view " << int(c.view) << ", question at step " << c.step);
    HeadlessHost host(kW, kH);
    host.set_mouse(std::nullopt, false);
    Session& s = host.app().session();
    REQUIRE(s.open_lesson(kLessons / c.lesson));
    REQUIRE(s.set_quiz(true));
    REQUIRE(s.set_view(c.view));
    const Question* q = reach(s, c.step);
    REQUIRE(q);
    const std::size_t shown = q->shown_step;
    CHECK(shown + 1 == c.step);  // none of these is a pixel question on a plot step
    CHECK(s.shown_step() == shown);
    const Frame waiting = capture(host);
    // The question and its answer buttons are in view, above the narration panel's bottom edge.
    CHECK(host.app().narration_marks().quiz_bottom <= host.app().layout().narration.bottom());

    // Answered (wrongly: the truth does not matter here), the frame is the question's own step.
    const Json wrong = q->type == QuizType::diverge ? Json(q->answer.get<std::size_t>() + 1)
                       : q->type == QuizType::branch ? Json(q->choices.front() == q->answer ? q->choices.back() : q->choices.front())
                       : q->type == QuizType::sign  ? Json(-q->answer.get<int>() + (q->answer.get<int>() == 0))
                                                    : Json(!q->answer.get<bool>());
    REQUIRE(s.answer(wrong));
    CHECK(s.shown_step() == c.step);
    const Frame answered = capture(host);
    CHECK(differing(answered, waiting) > 0);  // the gate hid something of the question's step

    // Back at the shown step, nothing differs from what the waiting question showed.
    s.go(shown);
    REQUIRE(s.step() == shown);
    const Frame before = capture(host);
    CHECK(differing(before.canvas, waiting.canvas) == 0);
    CHECK(differing(before.state, waiting.state) == 0);
    CHECK(differing(before.listing, waiting.listing) == 0);
  }
}

TEST_CASE("visualizer quiz gate: the sweep views wait for the last answer, and the tree view counts only what is built", "[visualizer][quiz][render]") {
  SECTION("image: the sweep appears when every question is answered") {
    HeadlessHost host(kW, kH);
    host.set_mouse(std::nullopt, false);
    Session& s = host.app().session();
    REQUIRE(s.open_lesson(kLessons / "06-far-sphere.md"));
    REQUIRE(s.set_quiz(true));
    REQUIRE(s.set_view(View::image));
    CHECK(s.hide_sweep());
    const Frame hidden = capture(host);
    for (const Question& q : s.quiz_session().questions()) {
      REQUIRE(reach(s, q.step) == &q);
      s.answer(q.answer);
    }
    CHECK_FALSE(s.hide_sweep());
    s.go(0);
    CHECK(differing(capture(host).canvas, hidden.canvas) > 0);
  }
  SECTION("tree: the quiz's diagram holds the nodes built so far") {
    HeadlessHost host(kW, kH);
    Session& s = host.app().session();
    REQUIRE(s.open_lesson(kLessons / "16-kd-sah.md"));
    REQUIRE(s.set_quiz(true));
    REQUIRE(s.set_view(View::tree));
    REQUIRE(reach(s, 5));
    host.render(3);
    const auto* tree = dynamic_cast<const TreeCanvas*>(host.app().canvas(0));
    REQUIRE(tree);
    // Built so far, by the trace itself: nodes whose first node item is at or before the shown step.
    const TreeDiagram whole = build_tree_diagram(*s.model(0));
    std::size_t built = 0;
    for (const auto& n : whole.nodes) built += n.first_step <= s.shown_step();
    CHECK(whole.nodes.size() > built);
    CHECK(tree->diagram().nodes.size() == built);
  }
}

TEST_CASE("visualizer quiz gate: a branch question's buttons wrap inside the narration panel", "[visualizer][quiz][render]") {
  HeadlessHost host(kW, kH);
  Session& s = host.app().session();
  REQUIRE(s.open_lesson(kLessons / "25-planner-skips.md"));
  REQUIRE(s.set_quiz(true));
  const Question* q = reach(s, 34);  // offers every line of the ray tracer's listing
  REQUIRE(q);
  REQUIRE(q->choices.size() >= 8);
  host.render(3);
  const ImGuiWindow* w = ImGui::FindWindowByName("Lesson###Narration");
  REQUIRE(w);
  INFO("narration panel " << w->Pos.x << " + " << w->Size.x << ", content reaches " << w->DC.CursorMaxPos.x);
  CHECK(w->DC.CursorMaxPos.x <= w->Pos.x + w->Size.x - w->WindowPadding.x + 0.5f);
}

#endif
