// [SECTION] loading: lessons, algorithms, re-runs after edits
// [SECTION] frame layout
// Keys and playback: panel_timeline.cpp. The canvases and the compare strip: panel_canvases.cpp.
#include "panels/app.hpp"
#include <algorithm>
#include <cmath>
#include "panels/view_registry.hpp"

namespace sw::vis {

App::App(TextureHost& textures, theme::Fonts fonts, std::filesystem::path lessons_dir)
    : textures_(&textures), base_fonts_(fonts), fonts_(fonts), lessons_dir_(std::move(lessons_dir)) {
  try {
    lessons_ = lesson_manifest(lessons_dir_);
  } catch (const InputError& e) {
    lessons_error_ = e.what();
  }
}

// [SECTION] loading: lessons, algorithms, re-runs after edits

bool App::open_first_lesson() {
  if (lessons_.empty()) {
    error_ = lessons_error_.empty() ? "no lessons in " + lessons_dir_.string() : lessons_error_;
    return false;
  }
  return open_lesson(lessons_.front());
}

bool App::open_lesson(const std::filesystem::path& file) {
  try {
    Lesson l = load_lesson(file);
    std::optional<Lesson> previous = std::move(lesson_);
    lesson_ = std::move(l);
    if (std::string err = load(*lesson_->algorithm, lesson_->input, lesson_->numeric, lesson_->compare, false); !err.empty()) {
      lesson_ = std::move(previous);
      error_ = file.filename().string() + ": " + err;
      return false;
    }
    quiz_ = {};
    if (lesson_->show) set_view(*lesson_->show);
    set_step(lesson_->start_step);
    if (lesson_->focus) jump_and_focus(lesson_->start_step);
    return true;
  } catch (const InputError& e) {
    error_ = e.what();
    return false;
  }
}

bool App::open_algorithm(const Algorithm& alg, const Json& input, Numeric numeric, Comparison compare) {
  if (std::string err = load(alg, input, numeric, compare, false); !err.empty()) {
    error_ = err;
    return false;
  }
  lesson_.reset();
  quiz_ = {};
  return true;
}

std::string App::load(const Algorithm& alg, const Json& input, Numeric numeric, Comparison compare, bool keep_view) {
  std::shared_ptr<const TraceModel> a, b;
  Json other_input;
  if (compare.other) compare.numeric = numeric;  // another algorithm runs in the left's number type
  try {
    // The input is parsed once: the compared number type runs the same opened input.
    const Run run = alg.open(input, numeric);
    a = record_model(run, budget_);
    if (compare.other) {
      const bool same = compare.other == compare_.other && other_input_.is_object();
      other_input = carried_input(input, same ? other_input_ : parse_json_text(compare.other->example, "example"));
      b = record_model(compare.other->open(other_input, numeric), budget_);
    } else if (compare) {
      b = record_model(run.in(*compare.numeric), budget_);
    }
  } catch (const std::exception& e) {  // InputError, or anything the run threw: show it, never crash
    return std::string(a && compare.other ? compare.other->id : alg.id) + ": " + e.what();
  }
  alg_ = &alg, input_ = input, numeric_ = numeric, compare_ = compare, other_input_ = std::move(other_input);
  a_ = std::move(a), b_ = std::move(b);
  stats_ = b_ ? std::optional(compare_traces(*a_, *b_)) : std::nullopt;
  // A re-run keeps the view shown if the algorithm has it; else its first declared view.
  const bool has_view = std::find(alg.views.begin(), alg.views.end(), view_) != alg.views.end();
  const View view = keep_view && has_view && canvases_[0] ? view_ : alg.views.empty() ? View::plane2d : alg.views.front();
  if (!keep_view)
    for (auto& pair : stashed_)
      for (auto& c : pair)
        if (c) c->fit();
  show_view(view);
  if (!keep_view) {
    canvases_[0]->fit();
    step_ = 0;
    playing_ = false;
  }
  // The timeline's "next of kind" starts on the kind that draws: plot, visit or hit.
  for (StepKind k : {StepKind::plot, StepKind::visit, StepKind::hit, StepKind::decide})
    if (a_->find_kind(0, k, true) || a_->trace().at(0).kind == k) {
      seek_kind_ = int(k);
      break;
    }
  error_.clear();
  edit_error_.clear();
  fill_endpoint_fields();
  json_text_ = input_.dump();
  step_ = std::min(step_, a_->last());
  return {};
}

bool App::rerun_with_input(const Json& input) {
  const double frac = steps() > 1 ? double(step_) / double(steps() - 1) : 0.0;
  if (std::string err = load(*alg_, input, numeric_, compare_, true); !err.empty()) {
    edit_error_ = err;
    return false;
  }
  step_ = static_cast<std::size_t>(std::llround(frac * double(a_->last())));
  return true;
}

// An edit re-runs at once: load() opens the input (one parse) and leaves the open run as it was
// when the input is bad.
void App::apply_input(const Json& input) {
  if (alg_) rerun_with_input(input);
}

void App::apply_other_input(const Json& other_input) {
  if (!alg_ || !compare_.other) return;
  const Json previous = std::exchange(other_input_, other_input);
  if (!rerun_with_input(input_)) other_input_ = previous;
}

bool App::set_numerics(Numeric numeric, Comparison compare) {
  if (!alg_) return false;
  if (std::string err = load(*alg_, input_, numeric, compare, true); !err.empty()) {
    error_ = err;
    return false;
  }
  return true;
}

void App::rerun_numerics(Numeric numeric, Comparison compare) {
  if (!alg_) return;
  if (std::string err = load(*alg_, input_, numeric, compare, true); !err.empty()) edit_error_ = err;
}

namespace {

Json rational_json(const Rational& r) {
  if (r.get_den() == 1 && abs(r) < Rational(1L << 53)) return Json(r.get_num().get_si());
  return Json(num::to_text(r));
}

}  // namespace

void App::on_drag(const CanvasEvents::Drag& d) {
  if (!alg_ || d.handle < 0 || d.handle >= static_cast<int>(alg_->handles.size())) return;
  const Handle& h = alg_->handles[d.handle];
  // Snap to the handle's grid so that exact values stay short; fall back to integers when the
  // number type needs them.
  for (long den : {static_cast<long>(std::max(h.snap, 1)), 1L}) {
    Json in = input_;
    Rational x(mpz_class(std::lround(d.x * double(den))), mpz_class(den)), y(mpz_class(std::lround(d.y * double(den))), mpz_class(den));
    x.canonicalize(), y.canonicalize();
    in[Json::json_pointer(h.pointer)] = Json::array({rational_json(x), rational_json(y)});
    if (in == input_ || rerun_with_input(in)) return;
  }
}

void App::fill_endpoint_fields() {
  handle_text_.clear();
  if (!alg_ || !input_.is_object()) return;
  for (const Handle& h : alg_->handles) {
    if (h.kind != Handle::Kind::point2) continue;
    const Json::json_pointer ptr(h.pointer);
    const Json* pt = input_.contains(ptr) ? &input_[ptr] : nullptr;
    std::array<std::string, 2> text;
    for (int a = 0; a < 2 && pt && pt->is_array() && pt->size() == 2; ++a) {
      try {
        text[a] = num::to_text(parse_rational((*pt)[a], h.label));
      } catch (const InputError&) {
        text[a] = (*pt)[a].dump();
      }
    }
    handle_text_.push_back(text);
  }
}

void App::show_view(View view) {
  if (view != view_ && canvases_[0]) stashed_[static_cast<std::size_t>(view_)] = std::move(canvases_);
  if (view != view_ || !canvases_[0]) {
    view_ = view;
    canvases_ = std::move(stashed_[static_cast<std::size_t>(view)]);
    for (auto& c : canvases_)
      if (!c) c = make_canvas(view_, *textures_);
  }
}

bool App::set_view(View view) {
  if (!alg_ || std::find(alg_->views.begin(), alg_->views.end(), view) == alg_->views.end()) return false;
  if (view != view_) view_tab_pending_ = true;
  show_view(view);
  return true;
}

void App::set_step(std::size_t step) {
  step = a_ ? std::min(step, a_->last()) : 0;
  step_ = quiz_.on ? quiz_gate(step) : step;
}

void App::restart_view() {
  for (auto& c : canvases_)
    if (c) c->fit();
  followed_step_ = ~std::size_t(0);
  // The panels' measured heights too: a fresh open fits the canvas on its first frame, at the size
  // the unmeasured layout gives, and the frames after settle from there.
  toolbar_content_h_ = timeline_content_h_ = 0, listing_content_h_ = kUnmeasuredListingH;
  listing_scrolled_to_ = ~std::size_t(0);
  if (lesson_ && lesson_->focus) jump_and_focus(lesson_->start_step);
}

void App::jump_and_focus(std::size_t step) {
  set_step(step);
  playing_ = false;
  if (a_ && canvases_[0]) canvases_[0]->focus(*a_, step_, 24.0);
}

// [SECTION] frame layout

void App::frame(float dt) {
  handle_keys();
  advance_playback(dt);
  fonts_ = presenting_ ? base_fonts_.big() : base_fonts_;
  ImGui::PushFont(fonts_.body);
  // Toolbar on top, timeline at the bottom, each as tall as its rows measured last frame; canvas
  // with the narration under it on the left; the listing and the state on the right (layout.cpp).
  LayoutInput in{ImGui::GetIO().DisplaySize, ImGui::GetFontSize(), toolbar_content_h_, timeline_content_h_, listing_content_h_};
  in.lesson = lesson_.has_value(), in.presenting = presenting_;
  const PanelLayout& l = layout_ = layout_panels(in);
  draw_toolbar(l.toolbar.pos, l.toolbar.size);
  draw_canvases(l.canvas.pos, l.canvas.size);
  draw_narration(l.narration.pos, l.narration.size);
  draw_listing(l.listing.pos, l.listing.size);
  if (!presenting_) draw_state(l.state.pos, l.state.size);
  draw_timeline(l.timeline.pos, l.timeline.size);
  accuracy_.draw(alg_, &accuracy_open_);
  ImGui::PopFont();
}

}  // namespace sw::vis
