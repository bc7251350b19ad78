// The visualizer's Session without a window or an OSMesa context (visualizer/lessons/session.hpp):
// opening lessons and algorithms, edits that open their input once (counted with inputs_opened),
// a bad edit that changes nothing, number types, the compare stats, the quiz's gate and answers,
// and the timeline. In sw_lessons, so the sanitizer build runs it too.
#include <catch2/catch.hpp>
#include <fstream>
#include "lessons/grading.hpp"
#include "lessons/session.hpp"
#include "cli_harness.hpp"
#include "host_options.hpp"
#include "source_paths.hpp"

using namespace sw;
using sw::testing::kLessons;
using namespace sw::vis;

namespace {

Json example(const Algorithm& alg) { return Json::parse(alg.example); }

}  // namespace

TEST_CASE("session: a lesson opens once, with its number types, start step and compare stats", "[session]") {
  Session s(kLessons);
  CHECK_FALSE(s.loaded());
  const auto opened = inputs_opened();
  REQUIRE(s.open_lesson(kLessons / "04-float-drift.md"));
  CHECK(inputs_opened() - opened == 1);  // the lesson's input, once: the exact run is the same opened input
  REQUIRE(s.lesson());
  CHECK(s.lesson()->title == "Float drift on a long DDA line");
  CHECK(s.algorithm() == &find_algorithm("dda-line"));
  CHECK(s.model(0)->numeric() == Numeric::f32);
  REQUIRE(s.model(1));
  CHECK(s.model(1)->numeric() == Numeric::exact);
  CHECK(s.run_name(0) == "float");
  CHECK(s.run_name(1) == "exact");
  // "step: 3939" and "view: step": there, with the canvas asked to focus on it (once).
  CHECK(s.step() == 3939);
  CHECK(s.take_focus() == std::optional<std::size_t>(3939));
  CHECK_FALSE(s.take_focus());
  // The stats are the two runs compared (docs/visualizer.md: 22 mismatched cells, 11 steps from 3939).
  REQUIRE(s.compare_stats());
  const CompareStats& st = *s.compare_stats();
  CHECK(st.steps_a == s.model(0)->size());
  CHECK(st.steps_b == s.model(1)->size());
  CHECK(st.mismatched_cells.size() == 22);
  CHECK(st.divergences.size() == 11);
  CHECK(st.first_decision_divergence == std::optional<std::size_t>(3939));
  CHECK(s.opens() == 1);
  CHECK(s.lesson_index() == std::optional<std::size_t>(3));
  // A lesson that fails to load leaves this one open, and says why in one line.
  CHECK_FALSE(s.open_lesson(kLessons / "missing.md"));
  CHECK(s.error().find('\n') == std::string::npos);
  CHECK_FALSE(s.error().empty());
  CHECK(s.lesson()->title == "Float drift on a long DDA line");
  CHECK(s.step() == 3939);
  // Next and previous in manifest order.
  REQUIRE(s.open_adjacent_lesson(+1));
  CHECK(s.lesson_index() == std::optional<std::size_t>(4));
  CHECK(s.error().empty());
  REQUIRE(s.open_adjacent_lesson(-1));
  CHECK(s.lesson()->title == "Float drift on a long DDA line");
  CHECK(s.opens() == 3);
}

TEST_CASE("session: an edit opens its input once and re-records every number type shown", "[session]") {
  Session s(kLessons);
  const Algorithm& dda = find_algorithm("dda-line");
  REQUIRE(s.open_algorithm(dda, Json::parse(R"({"p0":[0,0],"p1":[9,4]})"), Numeric::exact, Comparison(Numeric::f32)));
  CHECK(s.lesson() == nullptr);
  CHECK(s.view() == View::plane2d);
  s.set_step(s.steps() - 1);
  const auto loads = s.loads(), opens = s.opens();
  auto opened = inputs_opened();
  CHECK(s.apply_input(Json::parse(R"({"p0":[0,0],"p1":[18,8]})")).empty());
  CHECK(inputs_opened() - opened == 1);  // one parse, though two number types record it
  CHECK(s.loads() == loads + 1);
  CHECK(s.opens() == opens);  // an edit is not a fresh open: the canvases keep their view
  CHECK(s.input()["p1"] == Json::array({18, 8}));
  CHECK(s.model(0)->input() == s.input());
  CHECK(s.model(1)->input() == s.input());
  CHECK(s.model(0)->numeric() == Numeric::exact);
  CHECK(s.model(1)->numeric() == Numeric::f32);
  CHECK(s.step() == s.steps() - 1);  // the relative position is kept: the end stays the end
  REQUIRE(s.compare_stats());
  CHECK(s.compare_stats()->steps_a == s.model(0)->size());

  // A dragged handle: snapped to its grid (1/8), one parse.
  opened = inputs_opened();
  s.drag_handle(1, 12.3, 5.06);
  CHECK(inputs_opened() - opened == 1);
  CHECK(s.input()["p1"] == Json::array({"49/4", 5}));

  // A bad edit leaves everything as it was and says why in one line.
  const Json kept = s.input();
  const TraceModel* a = s.model(0);
  const std::size_t step = s.step();
  const std::string err = s.apply_input(Json::parse(R"({"p0":[0,0],"p1":["x",2]})"));
  CHECK_FALSE(err.empty());
  CHECK(err.find('\n') == std::string::npos);
  CHECK(s.edit_error() == err);
  CHECK(s.error().empty());  // not an opening error
  CHECK(s.input() == kept);
  CHECK(s.model(0) == a);
  CHECK(s.step() == step);
  CHECK(s.loads() == loads + 2);
  // The next good edit clears it.
  CHECK(s.apply_input(kept).empty());
  CHECK(s.edit_error().empty());

  // Other number types re-record the same opened input: no parse.
  opened = inputs_opened();
  REQUIRE(s.set_numerics(Numeric::f64, Comparison(Numeric::exact)));
  CHECK(inputs_opened() == opened);
  CHECK(s.model(0)->numeric() == Numeric::f64);
  CHECK(s.model(1)->numeric() == Numeric::exact);
  CHECK(s.input() == kept);
  // A number type the algorithm does not run on changes nothing.
  CHECK_FALSE(s.set_numerics(Numeric::integer, {}));
  CHECK_FALSE(s.error().empty());
  CHECK(s.model(0)->numeric() == Numeric::f64);
  REQUIRE(s.model(1));
  CHECK_FALSE(s.edit_numerics(Numeric::integer, {}).empty());
  CHECK(s.model(0)->numeric() == Numeric::f64);
  REQUIRE(s.set_numerics(Numeric::exact, {}));
  CHECK_FALSE(s.model(1));
  CHECK_FALSE(s.compare_stats());
}

TEST_CASE("session: another algorithm compared opens each input once", "[session]") {
  Session s(kLessons);
  const Algorithm &phong = find_algorithm("phong"), &beckmann = find_algorithm("beckmann");
  auto opened = inputs_opened();
  REQUIRE(s.open_algorithm(phong, example(phong), Numeric::f64, Comparison(Numeric::f64, &beckmann)));
  CHECK(inputs_opened() - opened == 2);  // phong's input and beckmann's, carried over
  CHECK(s.run_name(0) == "phong");
  CHECK(s.run_name(1) == "beckmann (double)");
  CHECK(s.model(1)->algorithm().id == "beckmann");
  CHECK(s.model(1)->input()["e"] == s.input()["e"]);
  // Its own parameter (m: phong has none): only its input is opened.
  Json other = s.other_input();
  other["m"] = 0.5;
  opened = inputs_opened();
  CHECK(s.apply_other_input(other).empty());
  CHECK(inputs_opened() - opened == 1);
  CHECK(s.other_input()["m"] == 0.5);
  // An edit of the left input: each input once, the other's own m kept.
  Json in = s.input();
  in["e"] = Json::array({-1, 0.5, 2});
  opened = inputs_opened();
  CHECK(s.apply_input(in).empty());
  CHECK(inputs_opened() - opened == 2);
  CHECK(s.other_input()["e"] == in["e"]);
  CHECK(s.other_input()["m"] == 0.5);
  // Another number type for both: no parse.
  opened = inputs_opened();
  REQUIRE(s.set_numerics(Numeric::f32, Comparison(Numeric::f32, &beckmann)));
  CHECK(inputs_opened() == opened);
  CHECK(s.model(1)->numeric() == Numeric::f32);
  CHECK(s.other_input()["m"] == 0.5);
}

TEST_CASE("session: views are the algorithm's, and a re-run keeps the one shown", "[session]") {
  Session s(kLessons);
  const Algorithm& poly = find_algorithm("poly-forward-diff");
  REQUIRE(s.open_algorithm(poly, example(poly), Numeric::f32));
  CHECK(s.view() == poly.views.front());
  const auto requests = s.view_requests();
  REQUIRE(s.set_view(View::table));
  CHECK_FALSE(s.set_view(View::image));  // not declared
  CHECK(s.view() == View::table);
  CHECK(s.view_requests() == requests + 1);
  REQUIRE(s.set_numerics(Numeric::exact, {}));
  CHECK(s.view() == View::table);
  s.next_view();
  CHECK(s.view() != View::table);
  REQUIRE(s.open_algorithm(find_algorithm("ray-box"), example(find_algorithm("ray-box")), Numeric::f64));
  CHECK(s.view() == find_algorithm("ray-box").views.front());
}

TEST_CASE("session: the quiz holds stepping at each question until it is answered", "[session]") {
  Session s(kLessons);
  REQUIRE(s.open_lesson(kLessons / "01-dda-line.md"));
  const auto opened = inputs_opened();
  REQUIRE(s.set_quiz(true));
  CHECK(inputs_opened() == opened);  // the lesson's opened input, in the quiz's number type
  CHECK(s.quiz());
  CHECK(s.step() == 0);
  CHECK(s.model(0)->numeric() == quiz_numeric(*s.lesson()));
  // The DDA plots (2, 3) first; the question there asks for the next pixel, (3, 3).
  const std::uint32_t first_plot = s.model(0)->step_of_cell({2, 3});
  s.set_step(s.steps() - 1);
  CHECK(s.step() == first_plot);  // the gate
  const Question* q = s.quiz_pending();
  REQUIRE(q);
  CHECK(q->type == QuizType::pixel);
  s.step_forward();
  CHECK(s.step() == first_plot);                 // still held
  CHECK_THROWS_AS(s.answer("hit"), InputError);  // not a cell: nothing recorded
  CHECK(s.quiz_score() == std::pair<int, int>{0, 0});
  const auto right = s.answer(Json::array({3, 3}));
  REQUIRE(right);
  CHECK(right->right);
  CHECK(s.quiz_score() == std::pair<int, int>{1, 1});
  CHECK_FALSE(s.quiz_pending());
  CHECK_FALSE(s.answer(Json::array({3, 3})));  // none waits
  CHECK(s.step() == first_plot);               // answering does not step
  // Playback stops at the next question.
  s.toggle_playing();
  for (int k = 0; k < 1000 && s.animating(); ++k) s.tick(0.1f);
  CHECK_FALSE(s.animating());
  CHECK(s.step() > first_plot);
  REQUIRE(s.quiz_pending());
  const auto wrong = s.answer(Json::array({-100, -100}));
  REQUIRE(wrong);
  CHECK_FALSE(wrong->right);
  CHECK(s.quiz_score() == std::pair<int, int>{1, 2});
  // Leaving the quiz brings the lesson back as it was.
  REQUIRE(s.set_quiz(false));
  CHECK(s.model(0)->numeric() == s.lesson()->numeric);
  CHECK(s.step() == s.lesson()->start_step);
  s.set_step(s.steps() - 1);
  CHECK(s.step() == s.steps() - 1);
  // No lesson, no quiz.
  REQUIRE(s.open_algorithm(find_algorithm("dda-line"), Json::parse(R"({"p0":[0,0],"p1":[9,4]})"), Numeric::exact));
  CHECK_FALSE(s.set_quiz(true));
}

TEST_CASE("session: quiz answers are saved as given, and grade_class grades the file", "[session][quiz]") {
  const std::filesystem::path dir = sw::testing::scratch("answers");
  Session s(kLessons);
  REQUIRE(s.open_lesson(kLessons / "01-dda-line.md"));
  s.save_answers_in(dir / "ann", "ann\nforged");
  CHECK(s.answers_file() == dir / "ann" / "01-dda-line.jsonl");
  REQUIRE(s.set_quiz(true));
  s.set_step(s.steps() - 1);  // held at the first question: the next pixel after (2, 3) is (3, 3)
  REQUIRE(s.answer(Json::array({3, 3})));
  CHECK(std::filesystem::exists(s.answers_file()));  // saved at once, the directory made
  s.set_step(s.steps() - 1);
  REQUIRE(s.quiz_pending());
  REQUIRE(s.answer(Json::array({-100, -100})));
  CHECK(s.answers_error().empty());
  // The saved file is what `stepwise quiz` grades: one student, the same score, in order.
  const ClassGrades g = grade_class(s.quiz_session().questions(), {s.answers_file()});
  CHECK(g.skipped.empty());
  REQUIRE(g.students == std::vector<std::string>{"ann\nforged"});
  REQUIRE(g.answers.size() == 2);
  CHECK(g.answers[0].right);
  CHECK_FALSE(g.answers[1].right);
  CHECK(printable_name(g.students[0]) == "\"ann\\nforged\"");  // printed escaped, on one line
  // A directory that cannot be made: the error is kept, the quiz goes on.
  std::ofstream(dir / "file") << "x";
  s.save_answers_in(dir / "file", "bob");
  REQUIRE(s.set_quiz(false));
  REQUIRE(s.set_quiz(true));
  s.set_step(s.steps() - 1);
  REQUIRE(s.answer(Json::array({3, 3})));
  CHECK_THAT(s.answers_error(), Catch::StartsWith("cannot save the answers"));
}

TEST_CASE("session: the timeline steps, seeks, steps over nested calls and plays", "[session]") {
  Session s(kLessons);
  const Algorithm& bezier = find_algorithm("bezier-de-casteljau");  // chords drawn by dda-line: nested calls
  REQUIRE(s.open_algorithm(bezier, example(bezier), Numeric::exact));
  const TraceModel& m = *s.model(0);
  CHECK(s.step() == 0);
  s.step_back();
  CHECK(s.step() == 0);
  s.step_forward();
  CHECK(s.step() == 1);
  s.set_step(std::size_t(1) << 40);
  CHECK(s.step() == m.last());  // clamped
  s.go(0);
  CHECK(s.timeline().seek_kind() == StepKind::plot);  // the kind that draws
  s.seek(true);
  const std::size_t first = s.step();
  CHECK(first == m.find_kind(0, StepKind::plot, true));
  s.seek(true);
  CHECK(s.step() == m.find_kind(first, StepKind::plot, true));
  s.seek(false);
  CHECK(s.step() == first);
  // Stepping over from inside a nested call: the next step of its listing or of the algorithm's.
  std::size_t inside = 0;
  while (inside < m.size() && m.trace().at(inside).scope == 0) ++inside;
  REQUIRE(inside < m.size());
  s.go(inside);
  s.step_over(true);
  CHECK(s.step() == m.step_over(inside, true));
  s.step_over(false);
  CHECK(s.step() == m.step_over(m.step_over(inside, true).value(), false));
  // Playback: 8 steps a second (the fourth speed); 1/16 s a frame is half a step.
  s.go(0);
  CHECK(s.timeline().speed() == 8);
  s.toggle_playing();
  CHECK(s.animating());
  for (int k = 0; k < 10; ++k) s.tick(0.0625f);
  CHECK(s.step() == 5);
  s.faster();
  CHECK(s.timeline().speed() == 15);
  s.toggle_playing();  // pause
  s.tick(0.0625f);
  CHECK(s.step() == 5);
  // Playing to the end stops there; Play from the end starts over.
  s.set_step(m.last() - 1);
  s.toggle_playing();
  for (int k = 0; k < 10; ++k) s.tick(0.0625f);
  CHECK_FALSE(s.animating());
  CHECK(s.step() == m.last());
  s.toggle_playing(true);
  CHECK(s.step() == 0);
  CHECK(s.animating());
  s.jump_and_focus(7);
  CHECK_FALSE(s.animating());
  CHECK(s.take_focus() == std::optional<std::size_t>(7));
}

// What both window hosts open from their options (visualizer/host_options.cpp): a lesson by its
// manifest number; a lesson's run in another number type or with another input keeps the lesson
// and its comparison; --algorithm opens no lesson; a bad option leaves one line in error().
TEST_CASE("session: the hosts' options open a lesson by number and keep it across --numeric and --input", "[session]") {
  const auto open = [](Session& s, HostOptions o) { return open_session(s, o); };
  SECTION("--lesson 04 --numeric double: lesson 04 (float against exact), its run in double, still against exact") {
    Session s(kLessons);
    HostOptions o;
    o.lesson = "04", o.numeric = "double";
    REQUIRE(open(s, o));
    REQUIRE(s.lesson());
    CHECK(s.lesson()->path.filename() == "04-float-drift.md");
    CHECK(s.numeric() == Numeric::f64);
    REQUIRE(s.comparison().numeric);
    CHECK(*s.comparison().numeric == Numeric::exact);
  }
  SECTION("--lesson 03 --input: the lesson stays, with the new input") {
    Session s(kLessons);
    HostOptions o;
    o.lesson = "03", o.input = R"({"p0":[0,0],"p1":[7,3]})";
    REQUIRE(open(s, o));
    REQUIRE(s.lesson());
    CHECK(s.lesson()->path.filename() == "03-bresenham.md");
    CHECK(s.input() == Json::parse(o.input));
  }
  SECTION("--algorithm: no lesson, the algorithm's example in double unless told") {
    Session s(kLessons);
    HostOptions o;
    o.algorithm = "bresenham-line";
    REQUIRE(open(s, o));
    CHECK_FALSE(s.lesson());
    CHECK(s.algorithm() == &find_algorithm("bresenham-line"));
    CHECK(s.numeric() == Numeric::f64);
  }
  SECTION("a number that names no manifest lesson, and an unknown number type, fail with one line") {
    Session s(kLessons);
    HostOptions o;
    o.lesson = "99";
    CHECK_FALSE(open(s, o));
    CHECK_FALSE(s.error().empty());
    Session t(kLessons);
    HostOptions p;
    p.lesson = "04", p.numeric = "quad";
    CHECK_FALSE(open(t, p));
    CHECK(t.error().find("quad") != std::string::npos);
    CHECK(t.error().find('\n') == std::string::npos);
  }
}
