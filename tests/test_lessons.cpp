// Lessons v2: section choice, templates, conditions, the lint on every lesson and on broken ones,
// and quizzes graded against the exact trace.
#include <catch2/catch.hpp>
#include <cmath>
#include <regex>
#include <set>
#include <fstream>
#include "lessons/lesson.hpp"
#include "lessons/quiz.hpp"
#include "lessons/trace_model.hpp"
#include "source_paths.hpp"

using namespace sw;
using sw::testing::kLessons;
using namespace sw::vis;

namespace {

std::shared_ptr<const TraceModel> run_of(const Lesson& l, Numeric n) { return record_model(*l.algorithm, l.input, n); }

std::optional<std::size_t> first_step_at(const TraceModel& m, std::string_view line) {
  const std::uint32_t id = m.algorithm().listing.find(line);
  for (std::size_t s = 0; s < m.size(); ++s)
    if (m.trace().at(s).scope == 0 && m.trace().at(s).line == id) return s;
  return std::nullopt;
}

}  // namespace

TEST_CASE("lessons: the most specific section wins and templates quote the run's values", "[lesson]") {
  // Bresenham from (1, 2) to (13, 7): A = 12, B = 5, so e starts at 2B - A = -2 (by hand).
  const Lesson l = parse_lesson(
      "---\nalgorithm: bresenham-line\ninput: {\"p0\":[1,2],\"p1\":[13,7]}\nnumeric: int\n---\nIntro.\n\n"
      "## on kind plot\nA plot.\n## on line plot\nPlot at e = {e}.\n## on line plot if e < 0\nBelow: e = {e}, i = {i}.\n"
      "## on step 0\nThe very first step.\n",
      "t.md");
  const auto m = run_of(l, Numeric::integer);
  CHECK(narrate(l, *m, 0) == "The very first step.");
  const auto plot = first_step_at(*m, "plot");
  REQUIRE(plot);
  CHECK(narrate(l, *m, *plot) == "Below: e = -2, i = 1.");
  // Some later plot has e >= 0: there the unconditioned line section speaks.
  bool saw_other = false;
  for (std::size_t s = *plot + 1; s < m->size(); ++s)
    if (m->trace().at(s).line == m->trace().at(*plot).line && m->trace().at(s).scope == 0) {
      const std::string t = narrate(l, *m, s);
      CHECK((t.rfind("Below: e = -", 0) == 0 || t.rfind("Plot at e = ", 0) == 0));
      if (t.rfind("Plot at e = ", 0) == 0) {
        saw_other = true;
        CHECK(t.find("= -") == std::string::npos);  // the condition held exactly where it should not
      }
    }
  CHECK(saw_other);
  const Filled bad = fill_templates("{nope} and {e:hex}", *m, *plot);
  CHECK(bad.problems.size() == 2);
}

TEST_CASE("lessons: exact values show with their decimal, and for-sections narrate one run", "[lesson]") {
  const Lesson l = parse_lesson(
      "---\nalgorithm: dda-line\ninput: {\"p0\":[0,0],\"p1\":[3,1]}\nnumeric: exact\ncompare: float\n---\n"
      "## on line plot\nq.y is {qy}.\n## on line plot for float\nIn float q.y is {qy}.\n",
      "t.md");
  const auto exact = run_of(l, Numeric::exact), fl = run_of(l, Numeric::f32);
  const auto plot = first_step_at(*exact, "plot");
  REQUIRE(plot);
  // The second plot has q.y = 1/3 exactly.
  std::size_t second = *plot + 1;
  while (second < exact->size() && exact->trace().at(second).line != exact->trace().at(*plot).line) ++second;
  REQUIRE(second < exact->size());
  CHECK(narrate(l, *exact, second) == "q.y is 1/3 \xE2\x89\x88 0.333333.");
  CHECK(narrate(l, *fl, second).rfind("In float q.y is 0.33333", 0) == 0);
}

TEST_CASE("lessons: a byte-order mark is skipped and a nested listing's line can be named", "[lesson]") {
  const Lesson l = parse_lesson(
      "\xEF\xBB\xBF---\nalgorithm: ray-triangles\ninput: {\"triangles\":[[[0,0,0],[1,0,0],[0,1,0]]],\"test\":\"mt\",\"ray\":{\"o\":[0.25,0.25,1],\"d\":[0,0,-1]}}\n---\n"
      "## on line ray-triangle-mt/u\nu = {u}.\n",
      "bom.md");
  const auto m = run_of(l, Numeric::exact);
  std::size_t shown = 0;
  for (std::size_t s = 0; s < m->size(); ++s)
    if (const std::string t = narrate(l, *m, s); !t.empty()) {
      CHECK(t == "u = 1/4 \xE2\x89\x88 0.25.");  // u is the weight of v1 = (1, 0, 0): the hit (1/4, 1/4) is 1/4 of the way
      ++shown;
    }
  CHECK(shown == 1);
}

TEST_CASE("lessons: every lesson passes the lint (every step of every run walked)", "[lesson][lint]") {
  for (const auto& f : lesson_manifest(kLessons)) {
    INFO(f);
    const auto problems = lint_lesson(f);
    for (const auto& p : problems) UNSCOPED_INFO(p);
    CHECK(problems.empty());
  }
}

TEST_CASE("lessons: the lint fails each broken lesson with the problem it holds", "[lesson][lint]") {
  // Each file's first front-matter comment says what the lint must report: "# expect: TEXT".
  const auto dir = std::filesystem::path(SW_SOURCE_DIR) / "tests" / "cases" / "lessons-broken";
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    std::ifstream in(e.path());
    std::string first, second;
    std::getline(in, first);
    std::getline(in, second);
    REQUIRE(second.rfind("# expect: ", 0) == 0);
    const std::string expect = second.substr(10);
    INFO(e.path().filename() << " should report: " << expect);
    const auto problems = lint_lesson(e.path());
    REQUIRE(!problems.empty());
    bool found = false;
    for (const auto& p : problems) {
      UNSCOPED_INFO(p);
      found |= p.find(expect) != std::string::npos && p.rfind(e.path().string() + ":", 0) == 0;
    }
    CHECK(found);
    ++files;
  }
  CHECK(files >= 10);
}

TEST_CASE("lessons: the shading and ray-tracing lessons narrate every call's entry and every decision", "[lesson]") {
  // Where a student stops: the first step of each nested call, and each decide, hit or miss step.
  for (const char* name : {"19-gouraud-phong.md", "20-minnaert-moon.md", "21-fresnel-grazing.md", "22-phong-blinn.md",
                           "23-shadow-acne.md", "24-glass-tir.md", "25-planner-skips.md"}) {
    const Lesson l = load_lesson(kLessons / name);
    const auto m = run_of(l, l.numeric);
    const TraceView& t = m->trace();
    std::set<std::string> silent;  // "listing/line kind"
    std::size_t stops = 0;
    for (std::size_t s = 0; s < t.size(); ++s) {
      const StepRecord& st = t.at(s);
      const bool entry = st.scope != 0 && (s == 0 || t.at(s - 1).scope != st.scope);
      const bool decision = st.kind == StepKind::decide || st.kind == StepKind::hit || st.kind == StepKind::miss;
      if (!entry && !decision) continue;
      ++stops;
      if (narrate(l, *m, s).empty())
        silent.insert((st.scope ? std::string(t.scope_id(st.scope)) : std::string(l.algorithm->id)) + " line " + std::to_string(st.line) +
                      " " + std::string(kind_name(st.kind)));
    }
    INFO(name << ": " << stops << " stops");
    for (const auto& s : silent) UNSCOPED_INFO("silent at " << s);
    CHECK(silent.empty());
  }
}

TEST_CASE("lessons: narration quotes a float run's numbers rounded, never 17 digits", "[lesson]") {
  // A decimal of more than 9 significant digits that a template put in a float or double run's
  // narration lacks a digit count ({t:4}); exact runs quote their fractions as they are.
  const std::regex long_decimal(R"((\d[\d]*\.\d+|\d+\.\d*)(e[-+]?\d+)?)");
  for (const auto& file : lesson_manifest(kLessons)) {
    const Lesson l = load_lesson(file);
    std::vector<std::shared_ptr<const TraceModel>> runs;
    runs.push_back(record_model(*l.run));
    if (l.compare_run) runs.push_back(record_model(*l.compare_run));
    for (const auto& m : runs) {
      if (m->numeric() != Numeric::f32 && m->numeric() != Numeric::f64) continue;
      for (std::size_t s = 0; s < m->size(); ++s) {
        const Narration* n = l.section_for(*m, s);
        if (!n) continue;
        const std::string text = narrate(l, *m, s);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), long_decimal); it != std::sregex_iterator(); ++it) {
          if (n->text.find(it->str()) != std::string::npos) continue;  // the author's own digits, not a template's
          std::string digits = (*it)[1].str();
          digits.erase(std::remove(digits.begin(), digits.end(), '.'), digits.end());
          digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));
          INFO(file.filename().string() << " (" << numeric_name(m->numeric()) << ") step " << s << ": " << it->str());
          CHECK(digits.size() <= 9);
        }
      }
    }
  }
}

TEST_CASE("lessons: the lint reports a broken template once, with how many more steps it fails at", "[lesson]") {
  const auto problems = lint_lesson(sw::testing::kSourceDir / "tests/cases/lessons-broken/unknown-template.md");
  std::size_t mentions = 0;
  for (const auto& p : problems)
    if (p.find("{nosuch}") != std::string::npos) {
      ++mentions;
      // dda-line from (0, 0) to (5, 2) plots the columns 0 to 4: the first plot step and 4 more.
      CHECK(p.find("(and at 4 more steps)") != std::string::npos);
    }
  CHECK(mentions == 1);
}

TEST_CASE("lessons: quiz answers are graded against the exact trace", "[lesson][quiz]") {
  SECTION("pixel: the DDA's next pixel") {
    // p0 = (1.25, 2.5), p1 = (12.75, 7.25): slope 4.75/11.5; at x = 2, y = 2.8098 -> (2, 3); at x = 3,
    // y = 3.2228 -> (3, 3) (by hand). So the question on the step that plots (2, 3) expects (3, 3).
    const Lesson l = load_lesson(kLessons / "01-dda-line.md");
    const auto m = run_of(l, quiz_numeric(l));
    const std::uint32_t s = m->step_of_cell({2, 3});
    REQUIRE(s != kNoStep);
    const auto q = question_at(l, *m, s);
    REQUIRE(q);
    REQUIRE(q->type == QuizType::pixel);
    CHECK(grade(*q, Json::array({3, 3})).right);
    CHECK_FALSE(grade(*q, Json::array({3, 4})).right);
    CHECK(grade(*q, Json::array({3, 4})).expected == "(3, 3)");
    CHECK_THROWS_AS(grade(*q, "up"), InputError);
  }
  SECTION("sign: Bresenham's first decision is negative") {
    const Lesson l = load_lesson(kLessons / "03-bresenham.md");
    const auto m = run_of(l, quiz_numeric(l));
    const auto at = first_step_at(*m, "signs");
    REQUIRE(at);
    const auto q = question_at(l, *m, *at);
    REQUIRE(q);
    REQUIRE(q->type == QuizType::sign);
    CHECK(grade(*q, "negative").right);  // e = 2B - A = 2 * 5 - 12 = -2
    CHECK_FALSE(grade(*q, 1).right);
    CHECK_FALSE(grade(*q, "zero").right);
  }
  SECTION("hit: the exact ray hits the shared edge, a wrong guess does not") {
    const Lesson l = load_lesson(kLessons / "05-triangle-crack.md");
    const auto m = run_of(l, quiz_numeric(l));
    const auto qs = quiz_questions(l, *m);
    const auto it = std::find_if(qs.begin(), qs.end(), [](const Question& q) { return q.type == QuizType::hit; });
    REQUIRE(it != qs.end());
    CHECK(grade(*it, "hit").right);  // the point (917/256, 917/256, 0) lies on the diagonal: u = 0
    CHECK_FALSE(grade(*it, false).right);
  }
  SECTION("branch: the grid walk's pick at a corner") {
    // The segment leaves its first cell through the corner (1/2, 7/2) at t = 1/16 (by hand), and
    // the listing steps the upward-owned axis first: after the first pick comes visit_up.
    const Lesson l = load_lesson(kLessons / "02-grid-walk.md");
    const auto m = run_of(l, quiz_numeric(l));
    const auto at = first_step_at(*m, "pick");
    REQUIRE(at);
    const auto q = question_at(l, *m, *at);
    REQUIRE(q);
    REQUIRE(q->type == QuizType::branch);
    CHECK(grade(*q, "visit_up").right);
    CHECK_FALSE(grade(*q, "test").right);  // offered: a pick is followed by visit_up or by the test
    CHECK_THROWS_AS(grade(*q, "no-such-line"), InputError);
  }

}

namespace {
// A float lesson's question at `step`, asked on its exact run beside its float run.
struct FloatQuestion {
  Lesson l;
  std::shared_ptr<const TraceModel> exact, flt;
  std::optional<Question> q;
  FloatQuestion(const char* lesson, std::size_t step)
      : l(load_lesson(kLessons / lesson)), exact(run_of(l, Numeric::exact)), flt(run_of(l, Numeric::f32)),
        q(question_at(l, *exact, step, nullptr, flt.get())) {}
};
}  // namespace

TEST_CASE("lessons: float questions are graded against both runs, flag and vs questions against the recorded value", "[lesson][quiz]") {
  SECTION("same: float's pixel at x = 1968 against exact's, read from both runs") {
    const FloatQuestion f("04-float-drift.md", 3938);
    const auto &exact = f.exact, &flt = f.flt;
    const auto& q = f.q;
    REQUIRE(q);
    REQUIRE(q->type == QuizType::same);
    const auto a = exact->pixel_at(q->answer_step), b = flt->pixel_at(q->answer_step);
    REQUIRE(a);
    REQUIRE(b);
    CHECK(a->x == 1968);
    const bool same = a->x == b->x && a->y == b->y;  // exact (1968, 656), float (1968, 657)
    CHECK(grade(*q, same ? "same" : "differs").right);
    CHECK_FALSE(grade(*q, !same).right);
    CHECK_THROWS_AS(grade(*q, "maybe"), InputError);
    CHECK_FALSE(question_at(f.l, *exact, 3938));  // no compared run: not asked
  }
  SECTION("diverge: the first plot where the runs' pixels differ") {
    const FloatQuestion f("08-forward-difference-drift.md", 221);
    const auto &exact = f.exact, &flt = f.flt;
    const auto& q = f.q;
    REQUIRE(q);
    REQUIRE(q->type == QuizType::diverge);
    std::optional<std::size_t> first;
    for (std::size_t k = 0; k < exact->plots().size() && k < flt->plots().size() && !first; ++k)
      if (exact->plots()[k].cell.x != flt->plots()[k].cell.x || exact->plots()[k].cell.y != flt->plots()[k].cell.y) first = exact->plots()[k].step;
    REQUIRE(first);
    CHECK(grade(*q, *first).right);
    CHECK_FALSE(grade(*q, *first + 2).right);
    CHECK(grade(*q, *first + 2).expected == "step " + std::to_string(*first));
    CHECK_THROWS_AS(grade(*q, -3), InputError);
  }
  SECTION("flag: total internal reflection, from the recorded cosine by the critical-angle test") {
    const Lesson l = load_lesson(kLessons / "24-glass-tir.md");
    const auto m = run_of(l, quiz_numeric(l));
    for (const std::size_t step : {std::size_t{110}, std::size_t{156}}) {
      const auto q = question_at(l, *m, step);
      REQUIRE(q);
      REQUIRE(q->type == QuizType::flag);
      const VarRecord* c = m->latest_var(step, "c");
      REQUIRE(c);
      const double cos_i = m->trace().component_double(*c, 0), n1 = 1.5;  // glass to air
      const bool tir = n1 * n1 * (1 - cos_i * cos_i) > 1;
      INFO("step " << step << ", cos " << cos_i);
      CHECK(grade(*q, tir ? "yes" : "no").right);
      CHECK(grade(*q, tir).right);
      CHECK_FALSE(grade(*q, !tir).right);
    }
  }
  SECTION("sign vs: the exact Fresnel factor at e.h = 1/sqrt(101) against 1/2") {
    const Lesson l = load_lesson(kLessons / "21-fresnel-grazing.md");
    const auto m = run_of(l, quiz_numeric(l));
    const auto q = question_at(l, *m, 3);
    REQUIRE(q);
    REQUIRE(q->type == QuizType::sign);
    REQUIRE(q->than == "1/2");
    const double c = 1 / std::sqrt(101.0), g = std::sqrt(1.5 * 1.5 - 1 + c * c);  // unpolarised, index 1.5
    const double F = 0.5 * std::pow((g - c) / (g + c), 2) * (1 + std::pow((c * (g + c) - 1) / (c * (g - c) + 1), 2));
    CHECK(F == Approx(0.573).epsilon(0.01));
    CHECK(grade(*q, F > 0.5 ? "above" : "below").right);
    CHECK(grade(*q, F > 0.5 ? 1 : -1).right);
    CHECK_FALSE(grade(*q, "equal").right);
    CHECK(answer_text(*q, Json(-1)) == "below");
  }
}

TEST_CASE("lessons: a template quotes the variable of the step's own listing before a callee's", "[lesson]") {
  // gouraud-vs-phong records i (the pixel column) and calls shade, which records its own i (the
  // light). Brute force: the newest record of i in a step of the same scope, else the newest at all.
  const Lesson l = load_lesson(kLessons / "19-gouraud-phong.md");
  const auto m = run_of(l, l.numeric);
  const TraceView& t = m->trace();
  int own_wins = 0;
  for (std::size_t s = 0; s < m->size(); ++s) {
    const VarRecord* same = nullptr;
    const VarRecord* newest = nullptr;
    for (std::size_t r = s + 1; r-- > 0 && !same;)
      for (std::uint32_t v = t.at(r).var_end; v-- > t.at(r).var_begin;)
        if (std::string_view(t.var_at(v).name) == "i") {
          if (!newest) newest = &t.var_at(v);
          if (t.at(r).scope == t.at(s).scope && !same) same = &t.var_at(v);
        }
    const VarRecord* want = same ? same : newest;
    REQUIRE(m->latest_var(s, "i") == want);
    own_wins += same && same != newest;
  }
  CHECK(own_wins > 0);  // the case arises: a callee's i is newer than the step's own
}
