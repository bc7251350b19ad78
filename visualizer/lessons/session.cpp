// [SECTION] opening: lessons, algorithms, number types
// [SECTION] edits: the input, the compared algorithm's input, a dragged handle
// [SECTION] views and the timeline
// [SECTION] the quiz
// The lessons of the manifest: session_lessons.cpp.
#include "lessons/session.hpp"
#include "lessons/grading.hpp"
#include "output.hpp"
#include <algorithm>
#include <cmath>

namespace sw::vis {

Session::Session(std::filesystem::path lessons_dir) : lessons_dir_(std::move(lessons_dir)) {
  try {
    lessons_ = lesson_manifest(lessons_dir_);
  } catch (const std::exception& e) {
    lessons_error_ = e.what();
  }
}

// [SECTION] opening: lessons, algorithms, number types

bool Session::open_lesson(const std::filesystem::path& file) {
  try {
    Lesson l = load_lesson(file);  // opens the lesson's input (and the compared algorithm's) once
    std::optional<Lesson> previous = std::exchange(lesson_, std::move(l));
    const Lesson& now = *lesson_;
    const std::optional<Run> other = now.compare.other ? now.compare_run : std::nullopt;
    if (std::string err = load(*now.run, now.compare, false, other); !err.empty()) {
      lesson_ = std::move(previous);
      error_ = file.filename().string() + ": " + err;
      return false;
    }
    quiz_.stop();
    if (now.show) set_view(*now.show);
    set_step(now.start_step);
    if (now.focus) jump_and_focus(now.start_step);
    return true;
  } catch (const std::exception& e) {
    error_ = e.what();
    return false;
  }
}

bool Session::open_algorithm(const Algorithm& alg, const Json& input, Numeric numeric, Comparison compare) {
  std::string err;
  try {
    err = load(alg.open(input, numeric), compare, false);
  } catch (const std::exception& e) {
    err = std::string(alg.id) + ": " + e.what();
  }
  if (!err.empty()) {
    error_ = err;
    return false;
  }
  lesson_.reset();
  quiz_.stop();
  return true;
}

std::string Session::load(const Run& run, Comparison compare, bool keep_view, const std::optional<Run>& other) {
  const Algorithm& alg = run.algorithm();
  const Numeric numeric = run.numeric();
  std::shared_ptr<const TraceModel> a, b;
  Json other_input;
  if (compare.other) compare.numeric = numeric;  // another algorithm runs in the left's number type
  try {
    a = record_model(run, budget_);
    if (other) {
      other_input = other->input();
      b = record_model(*other, budget_);
    } else if (compare.other) {
      const bool same = compare.other == compare_.other && other_input_.is_object();
      other_input = carried_input(run.input(), same ? other_input_ : parse_json_text(compare.other->example, "example"));
      b = record_model(compare.other->open(other_input, numeric), budget_);
    } else if (compare) {
      b = record_model(run.in(*compare.numeric), budget_);  // the same opened input
    }
  } catch (const std::exception& e) {  // InputError, or anything the run threw: show it, never crash
    return std::string(a && compare.other ? compare.other->id : alg.id) + ": " + e.what();
  }
  // A re-run keeps the view shown if the algorithm has it; else its first declared view.
  const bool has_view = std::find(alg.views.begin(), alg.views.end(), view_) != alg.views.end();
  view_ = keep_view && has_view && a_ ? view_ : alg.views.empty() ? View::plane2d : alg.views.front();
  alg_ = &alg, input_ = run.input(), numeric_ = numeric, compare_ = compare, other_input_ = std::move(other_input);
  a_ = std::move(a), b_ = std::move(b);
  stats_ = b_ ? std::optional(compare_traces(*a_, *b_)) : std::nullopt;
  if (!keep_view) {
    ++opens_;
    timeline_.set_step(0);
    timeline_.set_playing(false);
  }
  // The timeline's "next of kind" starts on the kind that draws: plot, visit or hit.
  for (StepKind k : {StepKind::plot, StepKind::visit, StepKind::hit, StepKind::decide})
    if (a_->find_kind(0, k, true) || a_->trace().at(0).kind == k) {
      timeline_.set_seek_kind(k);
      break;
    }
  error_.clear();
  edit_error_.clear();
  ++loads_;
  timeline_.set_step(std::min(timeline_.step(), a_->last()));
  return {};
}

// The compared algorithm's run in `numeric`, when it stays the same algorithm on the same input:
// no new parse.
std::optional<Run> Session::same_other(Numeric numeric, const Comparison& compare) const {
  if (!compare.other || compare.other != compare_.other || !b_) return std::nullopt;
  return b_->run().in(numeric);
}

bool Session::set_numerics(Numeric numeric, Comparison compare) {
  if (!a_) return false;
  std::string err;
  try {
    err = load(a_->run().in(numeric), compare, true, same_other(numeric, compare));
  } catch (const std::exception& e) {
    err = std::string(alg_->id) + ": " + e.what();
  }
  if (!err.empty()) error_ = err;
  return err.empty();
}

std::string Session::edit_numerics(Numeric numeric, Comparison compare) {
  if (!a_) return {};
  try {
    if (std::string err = load(a_->run().in(numeric), compare, true, same_other(numeric, compare)); !err.empty())
      edit_error_ = err;
  } catch (const std::exception& e) {
    edit_error_ = std::string(alg_->id) + ": " + e.what();
  }
  return edit_error_;
}

// [SECTION] edits: the input, the compared algorithm's input, a dragged handle

std::string Session::rerun(const Run& run, const std::optional<Run>& other) {
  const double frac = steps() > 1 ? double(step()) / double(steps() - 1) : 0.0;
  if (std::string err = load(run, compare_, true, other); !err.empty()) return edit_error_ = err;
  timeline_.set_step(static_cast<std::size_t>(std::llround(frac * double(a_->last()))));
  return {};
}

// One parse: the edited input is opened once, and the compared number type records the same
// opened input. A bad input leaves the open runs as they were.
std::string Session::apply_input(const Json& input) {
  if (!alg_) return {};
  try {
    return rerun(alg_->open(input, numeric_));
  } catch (const std::exception& e) {
    return edit_error_ = std::string(alg_->id) + ": " + e.what();
  }
}

std::string Session::apply_other_input(const Json& other_input) {
  if (!a_ || !compare_.other) return {};
  try {
    return rerun(a_->run(), compare_.other->open(carried_input(input_, other_input), numeric_));
  } catch (const std::exception& e) {
    return edit_error_ = std::string(compare_.other->id) + ": " + e.what();
  }
}

namespace {

Json rational_json(const Rational& r) {
  if (r.get_den() == 1 && abs(r) < Rational(std::int64_t(1) << 53)) return Json(num::int64_of(r.get_num()));
  return Json(num::to_text(r));
}

}  // namespace

void Session::drag_handle(int handle, double x, double y) {
  if (!alg_ || handle < 0 || handle >= static_cast<int>(alg_->handles.size())) return;
  const Handle& h = alg_->handles[std::size_t(handle)];
  // Snap to the handle's grid so that exact values stay short; fall back to integers when the
  // number type needs them.
  for (long den : {static_cast<long>(std::max(h.snap, 1)), 1L}) {
    Json in = input_;
    Rational rx(mpz_class(std::lround(x * double(den))), mpz_class(den)),
        ry(mpz_class(std::lround(y * double(den))), mpz_class(den));
    rx.canonicalize(), ry.canonicalize();
    in[Json::json_pointer(h.pointer)] = Json::array({rational_json(rx), rational_json(ry)});
    if (in == input_ || apply_input(in).empty()) return;
  }
}

// [SECTION] views and the timeline

std::string Session::run_name(int i) const {
  if (i == 1) return compare_.label();
  return compare_.other && alg_ ? std::string(alg_->id) : std::string(numeric_name(numeric_));
}

bool Session::set_view(View view) {
  if (!alg_ || std::find(alg_->views.begin(), alg_->views.end(), view) == alg_->views.end()) return false;
  if (view != view_) view_ = view, ++view_requests_;
  return true;
}

void Session::next_view() {
  if (!alg_ || alg_->views.size() < 2) return;
  const auto it = std::find(alg_->views.begin(), alg_->views.end(), view_);
  set_view(it == alg_->views.end() || it + 1 == alg_->views.end() ? alg_->views.front() : *(it + 1));
}

void Session::set_step(std::size_t step) {
  step = a_ ? std::min(step, a_->last()) : 0;
  const std::size_t gated = quiz_.gate(timeline_.step(), step);
  if (gated != step) timeline_.set_playing(false);
  timeline_.set_step(gated);
}

void Session::go(std::size_t step) {
  set_step(step);
  timeline_.set_playing(false);
}

void Session::step_back() {
  if (step() > 0) go(step() - 1);
}

void Session::step_forward() { go(step() + 1); }

void Session::step_over(bool forward) {
  if (!a_) return;
  if (const auto s = a_->step_over(step(), forward)) set_step(*s);
  timeline_.set_playing(false);
}

void Session::seek(bool forward) {
  if (!a_) return;
  if (const auto s = a_->find_kind(step(), timeline_.seek_kind(), forward)) go(*s);
}

void Session::toggle_playing(bool restart_at_end) {
  if (restart_at_end && !timeline_.playing() && a_ && step() >= a_->last()) set_step(0);
  timeline_.toggle();
}

void Session::tick(float dt) {
  if (!a_ || !timeline_.playing()) return;
  set_step(step() + timeline_.due(dt));
  if (step() >= a_->last()) timeline_.set_playing(false);
}

void Session::jump_and_focus(std::size_t step) {
  go(step);
  if (a_) focus_ = this->step();
}

// [SECTION] the quiz

bool Session::set_quiz(bool on) {
  if (on == quiz_.on()) return true;
  if (!lesson_) return false;
  const Lesson& l = *lesson_;
  // The quiz is checked against the exact run, so that is the run the student steps through:
  // the lesson's own input, opened when the lesson was read. Float questions need the compared
  // number type's run beside it.
  std::string err;
  try {
    const std::optional<Run> other = !on && l.compare.other ? l.compare_run : std::nullopt;
    const Comparison quiz_compare = quiz_compared_numeric(l) ? Comparison(*quiz_compared_numeric(l)) : Comparison{};
    err = load(l.run->in(on ? quiz_numeric(l) : l.numeric), on ? quiz_compare : l.compare, true, other);
  } catch (const std::exception& e) {
    err = std::string(l.algorithm->id) + ": " + e.what();
  }
  if (!err.empty()) {
    error_ = err;
    return false;
  }
  quiz_.stop();
  if (on) quiz_.start(quiz_questions(l, *a_, b_.get()));
  timeline_.set_playing(false);
  timeline_.set_step(0);
  set_step(on ? 0 : l.start_step);
  return true;
}

std::optional<Grade> Session::answer(const Json& a) {
  const std::optional<Grade> g = quiz_.answer(step(), a);
  if (g) save_answers();
  return g;
}

void Session::save_answers() {
  const std::filesystem::path file = answers_file();
  if (file.empty()) return;
  try {
    std::filesystem::create_directories(answers_dir_);
    OutputFile out(file);
    out.stream() << answers_jsonl(quiz_, student_);
    out.commit();
    answers_error_.clear();
  } catch (const std::exception& e) {
    answers_error_ = "cannot save the answers: " + one_line(e.what(), 200);
  }
}

void Session::save_answers_in(std::filesystem::path dir, std::string student) {
  answers_dir_ = std::move(dir);
  student_ = std::move(student);
}

void Session::set_student(std::string student) {
  student_ = std::move(student);
  if (quiz_.score().second > 0) save_answers();  // the saved answers carry the new name at once
}

std::filesystem::path Session::answers_file() const {
  if (answers_dir_.empty() || !lesson_) return {};
  return answers_dir_ / (lesson_->path.stem().string() + ".jsonl");
}

}  // namespace sw::vis
