// Quiz mode and lesson narration in the app, through the headless host: the gate at each
// question, an answer by clicking a cell, the score, and render's number types with a lesson.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <cmath>
#include "headless/headless.hpp"
#include "source_paths.hpp"

using namespace sw;
using sw::testing::kLessons;
using namespace sw::vis;

namespace {
}

TEST_CASE("visualizer quiz: stepping stops at each question, a clicked cell answers it", "[visualizer][quiz]") {
  HeadlessHost host(960, 600);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_lesson(kLessons / "01-dda-line.md"));
  REQUIRE(session.set_quiz(true));
  CHECK(session.step() == 0);
  // The DDA plots (2, 3) first, at the first plot step; the question there asks for the next
  // pixel, (3, 3) (y = 2.5 + 1.75 * 4.75/11.5 = 3.2228 at x = 3, by hand).
  const std::uint32_t first_plot = session.model(0)->step_of_cell({2, 3});
  session.set_step(session.steps() - 1);
  CHECK(session.step() == first_plot);  // the gate
  REQUIRE(session.quiz_pending());
  CHECK(session.quiz_pending()->type == QuizType::pixel);
  host.render(3);
  const auto r = app.canvas(0)->cell_rect({3, 3});
  REQUIRE(r);
  const ImVec2 centre((*r)[0] + ((*r)[2] - (*r)[0]) / 2, (*r)[1] + ((*r)[3] - (*r)[1]) / 2);
  host.set_mouse(centre, false);
  host.render(1);
  host.set_mouse(centre, true);
  host.render(1);
  host.set_mouse(centre, false);
  host.render(1);
  CHECK(session.quiz_pending() == nullptr);
  CHECK(session.quiz_score() == std::pair<int, int>{1, 1});
  CHECK(session.step() == first_plot);  // answering does not step: the student steps on
  // The next forward move stops at the next question, which a wrong answer leaves scored 1 of 2.
  session.set_step(session.steps() - 1);
  CHECK(session.step() > first_plot);
  REQUIRE(session.quiz_pending());
  const auto g = session.answer(Json::array({-100, -100}));
  REQUIRE(g);
  CHECK_FALSE(g->right);
  CHECK(session.quiz_score() == std::pair<int, int>{1, 2});
  // Leaving quiz mode brings the lesson back as it was.
  REQUIRE(session.set_quiz(false));
  session.set_step(session.steps() - 1);
  CHECK(session.step() == session.steps() - 1);
}

TEST_CASE("visualizer quiz: a lesson re-run in other number types keeps its narration", "[visualizer][lesson]") {
  HeadlessHost host(960, 600);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_lesson(kLessons / "04-float-drift.md"));
  REQUIRE(session.set_numerics(Numeric::exact, Comparison(Numeric::f64)));
  REQUIRE(session.lesson());
  REQUIRE(session.model(1));
  CHECK(session.model(0)->numeric() == Numeric::exact);
  CHECK(session.model(1)->numeric() == Numeric::f64);
  // A plot step: the exact run narrates its own section ("for exact"), with its value filled in.
  const std::size_t plot = session.model(0)->plots()[10].step;
  const std::string text = narrate(*session.lesson(), *session.model(0), plot);
  CHECK(text.rfind("Plot (", 0) == 0);
  CHECK(text.find("exact q_y") != std::string::npos);
  CHECK(text.find('{') == std::string::npos);
}
#endif
