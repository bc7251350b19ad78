// A session of the visualizer without its window: what is open (a lesson, or an algorithm with its
// input), its recorded runs (the left one and the compared one, with their CompareStats), the
// number types, the view shown, the work budget, the timeline and the quiz; and every operation
// the panels ask of it. No ImGui and no GL: tests/test_session.cpp drives it alone, the ImGui App
// (panels/app.hpp) draws it.
//
// Each input is opened (parsed) once per change: an edit opens the edited input once and records
// it in every number type shown (Run::in); switching number types, the quiz and a lesson's own
// runs open nothing new. An operation that fails leaves what was open unchanged and says why in
// one line: error() for opening, edit_error() for edits.
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>
#include "lessons/compare.hpp"
#include "lessons/lesson.hpp"
#include "lessons/quiz_session.hpp"
#include "lessons/timeline.hpp"
#include "lessons/trace_model.hpp"

namespace sw::vis {

class Session {
 public:
  explicit Session(std::filesystem::path lessons_dir = default_lessons_dir());

  // [SECTION] opening. None of these throws: on failure they return false and error() says why.
  bool open_lesson(const std::filesystem::path& file);
  bool open_algorithm(const Algorithm& alg, const Json& input, Numeric numeric, Comparison compare = {});
  bool open_first_lesson();
  // The lesson `delta` places after the open one in manifest order (the first with none open);
  // false at either end.
  bool open_adjacent_lesson(int delta);
  bool open_manifest_lesson(std::size_t k);  // entry k of the manifest
  // Re-records what is open (a lesson stays open, its narration with it) in other number types.
  bool set_numerics(Numeric numeric, Comparison compare);
  bool loaded() const { return a_ != nullptr; }
  const std::string& error() const { return error_; }
  void show_error(std::string message) { error_ = std::move(message); }
  void dismiss_error() { error_.clear(); }
  // The work budget every run it records is held to (docs/cli.md).
  void set_budget(const Budget& budget) { budget_ = budget; }

  // [SECTION] edits, which keep the timeline's relative position. On failure they leave the runs
  // as they were and return the one-line error, which edit_error() keeps until the next success.
  std::string apply_input(const Json& input);
  // The compared algorithm's own input (its sliders).
  std::string apply_other_input(const Json& other_input);
  // The toolbar's number types: as set_numerics, the error going to edit_error().
  std::string edit_numerics(Numeric numeric, Comparison compare);
  // Declared handle `handle` dragged to world (x, y): snapped to its grid, or to integers where
  // the number type needs them.
  void drag_handle(int handle, double x, double y);
  const std::string& edit_error() const { return edit_error_; }
  void set_edit_error(std::string message) { edit_error_ = std::move(message); }

  // [SECTION] what is open
  const Lesson* lesson() const { return lesson_ ? &*lesson_ : nullptr; }
  const Algorithm* algorithm() const { return alg_; }
  const Json& input() const { return input_; }
  const Json& other_input() const { return other_input_; }  // the compared algorithm's
  Numeric numeric() const { return numeric_; }
  const Comparison& comparison() const { return compare_; }
  // Run 0 (the left) and run 1 (the compared one, if any).
  const TraceModel* model(int i) const { return (i == 0 ? a_ : b_).get(); }
  const std::shared_ptr<const TraceModel>& model_ptr(int i) const { return i == 0 ? a_ : b_; }
  const std::optional<CompareStats>& compare_stats() const { return stats_; }
  // The name a run goes by beside the other: its number type, or (two algorithms) its id.
  std::string run_name(int i) const;

  // [SECTION] views: one the algorithm declares; its first on opening; a re-run keeps it.
  View view() const { return view_; }
  bool set_view(View view);  // false if the algorithm declares no such view
  void next_view();          // V
  // Counters the App compares to see what changed since it last looked: successful loads, fresh
  // opens (not re-runs: the canvases fit), set_view calls that changed the view.
  std::uint64_t loads() const { return loads_; }
  std::uint64_t opens() const { return opens_; }
  std::uint64_t view_requests() const { return view_requests_; }

  // [SECTION] the timeline. Moves are clamped to the trace and, in a quiz, held at the first
  // unanswered question (which also stops playback).
  const Timeline& timeline() const { return timeline_; }
  std::size_t step() const { return timeline_.step(); }
  // The step the views, the state and the narration show: step(), except at a waiting quiz
  // question, whose frame must not give its answer away (Question::shown_step).
  std::size_t shown_step() const { return quiz_.shown(step()); }
  // Quiz mode: views say nothing of steps after shown_step(), and hide what a whole sweep shows
  // until every question is answered.
  bool hide_future() const { return quiz_.on(); }
  bool hide_sweep() const { return quiz_.on() && !quiz_.finished(); }
  std::size_t steps() const { return a_ ? a_->size() : 0; }
  void set_step(std::size_t step);
  void step_back();              // Left: one step, and pause
  void step_forward();           // Right
  void step_over(bool forward);  // Down/Up: past nested calls
  void seek(bool forward);       // the next or previous step of the timeline's seek kind
  void go(std::size_t step);     // a jump (Home, End, a click): there, and pause
  void set_playing(bool on) { timeline_.set_playing(on); }
  // Play or pause (Space); the Play button passes restart_at_end: from the end it starts over.
  void toggle_playing(bool restart_at_end = false);
  void faster() { timeline_.faster(); }
  void slower() { timeline_.slower(); }
  void set_seek_kind(StepKind k) { timeline_.set_seek_kind(k); }
  void tick(float dt);  // playback: dt seconds later
  bool animating() const { return timeline_.playing(); }
  // Goes to a step and asks the canvas to centre on it (take_focus: the step, once).
  void jump_and_focus(std::size_t step);
  std::optional<std::size_t> take_focus() { return std::exchange(focus_, std::nullopt); }

  // [SECTION] the quiz (a lesson only): the run switches to the quiz's exact number type from
  // step 0 (beside the lesson's other number type, when it compares two), stepping forward stops
  // at each question until it is answered.
  bool set_quiz(bool on);
  bool quiz() const { return quiz_.on(); }
  const QuizSession& quiz_session() const { return quiz_; }
  const Question* quiz_pending() const { return quiz_.pending(step()); }
  // Answers the waiting question (throws InputError for an answer of the wrong form); its grade,
  // or nullopt if none waits.
  std::optional<Grade> answer(const Json& answer);
  std::pair<int, int> quiz_score() const { return quiz_.score(); }
  // Saves each answer as it is given into DIR/<lesson file stem>.jsonl, under the student's name
  // (grading.hpp's lines, which `stepwise quiz` grades), rewriting the file whole; an empty DIR
  // saves nothing. A failure is kept in answers_error(), not thrown: the quiz goes on.
  void save_answers_in(std::filesystem::path dir, std::string student);
  // Where the open lesson's answers go ("" when not saved), and the last save's failure ("" if none).
  std::filesystem::path answers_file() const;
  const std::string& answers_error() const { return answers_error_; }
  const std::string& student() const { return student_; }
  // The name the answers are saved under, from now on and in the file already saved.
  void set_student(std::string student);

  // [SECTION] the lessons of the manifest (session_lessons.cpp)
  const std::vector<std::filesystem::path>& lessons() const { return lessons_; }
  const std::string& lessons_error() const { return lessons_error_; }
  // Each lesson's title (a file that fails to load: its name and the error), read once.
  const std::vector<std::string>& lesson_titles();
  // The manifest entry of the open lesson, if any.
  std::optional<std::size_t> lesson_index() const;

 private:
  // Records `run` and the comparison (the same input in another number type, or the other
  // algorithm: `other` if given, else opened on the input carried over) and makes them what is
  // open; on failure returns the message and leaves everything as it was.
  std::string load(const Run& run, Comparison compare, bool keep_view, const std::optional<Run>& other = {});
  std::string rerun(const Run& run, const std::optional<Run>& other = {});  // keeps the relative step
  std::optional<Run> same_other(Numeric numeric, const Comparison& compare) const;
  void save_answers();  // the quiz's answers so far into answers_file(), if answers are saved

  std::filesystem::path lessons_dir_;
  std::vector<std::filesystem::path> lessons_;
  std::string lessons_error_;
  std::vector<std::string> lesson_titles_;
  std::optional<std::size_t> lesson_pos_;  // the manifest entry last opened (or tried)

  std::optional<Lesson> lesson_;
  const Algorithm* alg_ = nullptr;
  Json input_, other_input_;
  Numeric numeric_ = Numeric::exact;
  Comparison compare_;
  Budget budget_;
  std::shared_ptr<const TraceModel> a_, b_;
  std::optional<CompareStats> stats_;
  View view_ = View::plane2d;
  std::uint64_t loads_ = 0, opens_ = 0, view_requests_ = 0;
  Timeline timeline_;
  std::optional<std::size_t> focus_;
  QuizSession quiz_;
  std::filesystem::path answers_dir_;
  std::string student_, answers_error_;
  std::string error_, edit_error_;
};

}  // namespace sw::vis
