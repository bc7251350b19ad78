#include "panels/accuracy_panel.hpp"
#include <imgui.h>
#include <optional>
#include "panels/chart_draw.hpp"
#include "panels/theme.hpp"

namespace sw::vis {

AccuracyRun::AccuracyRun(const Algorithm& alg, std::string set, int repeats) : alg_(&alg), repeats_(repeats), set_(std::move(set)) {
  if constexpr (kHaveThreads) thread_ = std::thread([this] {
      while (advance()) {}  // bounded: one call a mode
    });
}

AccuracyRun::~AccuracyRun() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

bool AccuracyRun::advance() {
  if (finished_) return false;
  try {
    if (!started_) {
      std::vector<std::string> names = alg_->bench_sets();
      std::lock_guard lock(mu_);
      sets_ = names;
      if (set_.empty() && !names.empty()) set_ = names.front();
      started_ = true;
    }
    // One mode at a time: stop_ is honoured between modes.
    if (!stop_ && done_ < alg_->numerics.size()) {
      Numeric n = alg_->numerics[done_];
      BenchOptions options;  // the default's cases (at most kQuickCases a set)
      options.repeats = repeats_, options.only_set = set();
      std::vector<BenchRow> got = alg_->bench(std::span(&n, 1), options);
      {
        std::lock_guard lock(mu_);
        rows_.insert(rows_.end(), got.begin(), got.end());
      }
      ++done_;
    }
  } catch (const std::exception& e) {
    std::lock_guard lock(mu_);
    error_ = e.what();
    finished_ = true;
    return false;
  }
  if (stop_ || done_ == alg_->numerics.size()) finished_ = true;
  return !finished_;
}

std::vector<BenchRow> AccuracyRun::rows() const {
  std::lock_guard lock(mu_);
  return rows_;
}

std::string AccuracyRun::error() const {
  std::lock_guard lock(mu_);
  return error_;
}

std::vector<std::string> AccuracyRun::sets() const {
  std::lock_guard lock(mu_);
  return sets_;
}

std::string AccuracyRun::set() const {
  std::lock_guard lock(mu_);
  return set_;
}

void AccuracyWindow::reap() {
  std::erase_if(retiring_, [](const std::unique_ptr<AccuracyRun>& r) { return r->finished(); });  // joins in the destructor
}

void AccuracyWindow::draw(const Algorithm* alg, bool* open) {
  reap();
  auto retire = [&] {  // closing never waits for the thread: it stops after its mode, joined later
    if (run_) run_->cancel(), retiring_.push_back(std::move(run_));
  };
  if (!*open || !alg) return retire();
  if (!run_ || &run_->algorithm() != alg) retire(), run_ = std::make_unique<AccuracyRun>(*alg, "");
  const ImVec2 d = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowSize(ImVec2(std::min(d.x - 40, 900.f), std::min(d.y - 60, 560.f)), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(d.x / 2, d.y / 2), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Accuracy", open, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  if (!kHaveThreads) run_->advance();  // a mode a frame
  const AccuracyRun& r = *run_;
  const std::string set = r.set();
  ImGui::TextUnformatted("Bench set");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(140);
  std::optional<std::string> chosen;
  if (ImGui::BeginCombo("##benchset", set.empty() ? "..." : set.c_str())) {
    for (const std::string& name : r.sets())
      if (ImGui::Selectable(name.c_str(), name == set) && name != set) chosen = name;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (!r.finished()) {
    const std::size_t done = r.modes_done(), all = r.modes();
    char text[96];
    std::snprintf(text, sizeof text, "timing %s (%zu of %zu modes)", done < all ? std::string(numeric_name(alg->numerics[done])).c_str() : "", done, all);
    ImGui::ProgressBar(all ? float(done) / float(all) : 0.f, ImVec2(-1, 0), text);
  } else if (const std::string err = r.error(); !err.empty()) {
    ImGui::TextColored(theme::kError, "bench failed: %s", err.c_str());
  } else {
    ImGui::TextDisabled("one repeat per mode; for slides: stepwise bench %s --set %s --plot FILE.png", std::string(alg->id).c_str(), set.c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("Run again")) chosen = set;
  }
  if (chosen) retire(), run_ = std::make_unique<AccuracyRun>(*alg, *chosen);
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  if (run_ && avail.x > 80 && avail.y > 80) {
    const std::vector<BenchRow> rows = run_->rows();
    chart_ = bench_chart(alg->id, rows, avail.x, avail.y, bench_chart_note(rows, 1));
    origin_ = ImGui::GetCursorScreenPos();
    paint_chart(ImGui::GetWindowDrawList(), chart_, origin_);
    ImGui::Dummy(avail);
  }
  ImGui::End();
}

}  // namespace sw::vis
