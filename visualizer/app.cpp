// [SECTION] loading: lessons, algorithms, re-runs after edits
// [SECTION] keys and playback
// [SECTION] frame layout
// [SECTION] canvases and the compare strip
#include "app.hpp"
#include <algorithm>
#include <cmath>
#include "view_registry.hpp"

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
    a = record_model(alg, input, numeric, budget_);
    if (compare.other) {
      const bool same = compare.other == compare_.other && other_input_.is_object();
      other_input = carried_input(input, same ? other_input_ : parse_json_text(compare.other->example, "example"));
      b = record_model(*compare.other, other_input, numeric, budget_);
    } else if (compare) {
      b = record_model(alg, input, *compare.numeric, budget_);
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

std::string App::validate_runs(const Json& input) const {
  try {
    alg_->validate(input, numeric_);
    if (compare_.other) compare_.other->validate(carried_input(input, other_input_), numeric_);
    else if (compare_) alg_->validate(input, *compare_.numeric);
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

void App::apply_input(const Json& input) {
  if (!alg_) return;
  if (std::string err = validate_runs(input); !err.empty()) {
    edit_error_ = err;
    return;
  }
  rerun_with_input(input);
}

void App::apply_other_input(const Json& other_input) {
  if (!alg_ || !compare_.other) return;
  try {
    compare_.other->validate(other_input, numeric_);
  } catch (const InputError& e) {
    edit_error_ = std::string(compare_.other->id) + ": " + e.what();
    return;
  }
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
    if (std::string err = validate_runs(in); !err.empty()) {
      edit_error_ = err;
      continue;
    }
    if (in != input_) rerun_with_input(in);
    return;
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

// [SECTION] keys and playback

void App::handle_keys() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantTextInput || !a_) return;
  auto pressed = [](ImGuiKey k) { return ImGui::IsKeyPressed(ImGui::GetKeyIndex(k)); };
  if (pressed(ImGuiKey_Space)) playing_ = !playing_, carry_ = 0;
  if (pressed(ImGuiKey_Escape)) presenting_ = false;
  if (io.KeyCtrl) {  // Ctrl + Left/Right: the previous or next lesson
    if (pressed(ImGuiKey_LeftArrow)) open_adjacent_lesson(-1);
    if (pressed(ImGuiKey_RightArrow)) open_adjacent_lesson(+1);
  } else if (!io.KeyShift) {  // Shift + arrows pan the canvas
    if (pressed(ImGuiKey_LeftArrow) && step_ > 0) set_step(step_ - 1), playing_ = false;
    if (pressed(ImGuiKey_RightArrow)) set_step(step_ + 1), playing_ = false;
  }
  if (pressed(ImGuiKey_Home)) set_step(0);
  if (pressed(ImGuiKey_End)) set_step(a_->last());
  for (ImWchar ch : io.InputQueueCharacters) {
    if (ch == '+' || ch == '=') speed_ = std::min<int>(speed_ + 1, int(kSpeeds.size()) - 1);
    if (ch == '-' || ch == '_') speed_ = std::max(speed_ - 1, 0);
    if (ch == 'p' || ch == 'P') presenting_ = !presenting_;
    if ((ch == 'v' || ch == 'V') && alg_ && alg_->views.size() > 1) {  // the next declared view
      const auto it = std::find(alg_->views.begin(), alg_->views.end(), view_);
      set_view(it == alg_->views.end() || it + 1 == alg_->views.end() ? alg_->views.front() : *(it + 1));
    }
    if ((ch == 'q' || ch == 'Q') && lesson_) set_quiz(!quiz_.on);
  }
}

void App::advance_playback(float dt) {
  if (!playing_ || !a_) return;
  // The window host sleeps while idle: the first frame after a wake-up may report a long dt.
  carry_ += double(std::min(dt, 0.1f)) * kSpeeds[speed_];
  const double whole = std::floor(carry_);
  carry_ -= whole;
  set_step(step_ + static_cast<std::size_t>(whole));
  if (step_ >= a_->last()) playing_ = false;
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

// [SECTION] canvases and the compare strip

void App::draw_canvases(ImVec2 pos, ImVec2 size) {
  constexpr ImGuiWindowFlags kFixed = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                      ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoScrollbar |
                                      ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoTitleBar |
                                      ImGuiWindowFlags_NoBackground;  // the canvas covers it: save llvmpipe a fill
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(4, 4));
  ImGui::Begin("Canvas", nullptr, kFixed);
  if (!error_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, theme::kError);
    ImGui::TextWrapped("Could not load: %s", error_.c_str());
    ImGui::PopStyleColor();
    if (a_ && ImGui::SmallButton("Dismiss")) error_.clear();
  }
  if (b_) draw_compare_strip();
  draw_view_tabs();
  ImVec2 avail = ImGui::GetContentRegionAvail();
  if (a_ && canvases_[0]) {
    const int n = b_ ? 2 : 1;
    const float w = (avail.x - float(n - 1) * 4) / float(n);
    const std::string label_a = compare_.other ? Comparison(numeric_, alg_).label() : std::string(numeric_name(numeric_)), label_b = compare_.label();
    for (int i = 0; i < n; ++i) {
      if (i) ImGui::SameLine(0, 4);
      ImGui::PushID(i);
      if (i) canvases_[1]->follow(*canvases_[0]);
      // Keep the step in view while playing and after each step taken, never against a pan.
      const bool follow = i == 0 && (playing_ || step_ != followed_step_);
      CanvasInput in{i ? b_ : a_, std::min(step_, (i ? b_ : a_)->last()), true, i == 0, follow, n > 1 ? (i ? label_b : label_a).c_str() : "", quiz_.on, {}};
      if (stats_ && !compare_.other) in.marked = stats_->mismatched_cells;
      const CanvasEvents ev = canvases_[i]->draw(in, ImVec2(w, avail.y));
      const Question* q = quiz_pending();
      if (ev.clicked_cell && q && q->type == QuizType::pixel) answer(Json::array({ev.clicked_cell->x, ev.clicked_cell->y}));
      else if (ev.jump_to) set_step(*ev.jump_to), playing_ = false;
      if (ev.drag) on_drag(*ev.drag);
      if (ev.edit) apply_input(*ev.edit);
      ImGui::PopID();
    }
    if (b_) canvases_[0]->follow(*canvases_[1]);  // a pan on the right canvas moves both
    followed_step_ = step_;
  } else if (error_.empty()) {
    ImGui::TextDisabled("Open a lesson or choose an algorithm above.");
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

void App::draw_view_tabs() {
  if (!alg_ || alg_->views.size() < 2) return;
  std::optional<View> chosen;
  if (ImGui::BeginTabBar("##views")) {
    for (View v : alg_->views) {
      const ViewInfo& info = view_info(v);
      if (ImGui::BeginTabItem(info.label, nullptr, v == view_ && view_tab_pending_ ? ImGuiTabItemFlags_SetSelected : 0)) {
        if (v == view_) view_tab_pending_ = false;
        else if (!view_tab_pending_) chosen = v;
        ImGui::EndTabItem();
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s (V: the next view)", info.help);
    }
    ImGui::EndTabBar();
  }
  if (chosen) show_view(*chosen);
}

void App::draw_compare_strip() {
  const CompareStats& s = *stats_;
  if (compare_.other) {  // two algorithms: their results side by side (their steps do not pair up)
    auto outcome = [](const TraceModel& m) {
      const Json& r = m.result();
      if (r.is_object() && r.contains("value")) return "value " + (r["value"].is_number() ? std::to_string(r["value"].get<double>()) : r["value"].dump());
      return std::string(m.size() ? "done" : "no steps");
    };
    ImGui::Text("%s: %zu steps, %s    %s: %zu steps, %s", std::string(alg_->id).c_str(), s.steps_a, outcome(*a_).c_str(), std::string(compare_.other->id).c_str(),
                s.steps_b, outcome(*b_).c_str());
    ImGui::TextDisabled("Both run on the keys their inputs share; each one's own parameters have their own sliders.");
    return;
  }
  const std::string na(numeric_name(numeric_)), nb(numeric_name(*compare_.numeric));
  if (std::find(alg_->views.begin(), alg_->views.end(), View::plane2d) != alg_->views.end()) {
    ImGui::Text("%s: %zu steps, %zu pixels    %s: %zu steps, %zu pixels    ", na.c_str(), s.steps_a, s.pixels_a, nb.c_str(), s.steps_b, s.pixels_b);
    ImGui::SameLine();
    ImGui::TextColored(s.pixel_mismatches ? theme::kError : theme::kGood, "%zu mismatched pixels", s.pixel_mismatches);
  } else {  // no pixels to count: compare the two outcomes (hit or miss)
    auto outcome = [](const TraceModel& m) { return m.result().is_object() && m.result().contains("hit") ? (m.result()["hit"] == true ? "hit" : "miss") : "done"; };
    const std::string oa = outcome(*a_), ob = outcome(*b_);
    ImGui::Text("%s: %zu steps, %s    %s: %zu steps, %s    ", na.c_str(), s.steps_a, oa.c_str(), nb.c_str(), s.steps_b, ob.c_str());
    ImGui::SameLine();
    ImGui::TextColored(oa != ob ? theme::kError : theme::kGood, oa != ob ? "different outcomes" : "same outcome");
  }
  if (s.first_decision_divergence) {
    if (ImGui::SmallButton("Jump to first divergence")) jump_and_focus(*s.first_decision_divergence);
    ImGui::SameLine();
    ImGui::Text("step %zu: line, kind or pixel differ", *s.first_decision_divergence);
  } else {
    ImGui::TextColored(theme::kGood, "Same decisions and pixels at every step.");
  }
  if (s.first_value_divergence) {
    ImGui::SameLine(0, 24);
    if (ImGui::SmallButton("Jump to first value difference")) jump_and_focus(*s.first_value_divergence);
    ImGui::SameLine();
    ImGui::Text("step %zu", *s.first_value_divergence);
  }
}

}  // namespace sw::vis
