#include "panels/scene_view.hpp"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include "lessons/result_keys.hpp"
#include "panels/theme.hpp"

namespace sw::vis {
namespace {

ImU32 rgb_u32(const std::array<double, 3>& c) {
  auto b = [](double x) { return int(std::lround(255 * std::clamp(std::isfinite(x) ? x : 0.0, 0.0, 1.0))); };
  return IM_COL32(b(c[0]), b(c[1]), b(c[2]), 255);
}

// A colour as a swatch (its tooltip has the components), then the text if any.
void colour_cell(const std::array<double, 3>& c, const std::string& text) {
  const ImVec2 p = ImGui::GetCursorScreenPos();
  const float h = ImGui::GetTextLineHeight();
  ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, p.y + 2), ImVec2(p.x + h - 4, p.y + h - 2), rgb_u32(c));
  ImGui::Dummy(ImVec2(h - 2, h));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("rgb(%.6g, %.6g, %.6g)", c[0], c[1], c[2]);
  if (text.empty()) return;
  ImGui::SameLine();
  ImGui::TextUnformatted(text.c_str());
}

void cell(const SummaryTable::Cell& c) {
  if (c.rgb) colour_cell(*c.rgb, c.text);
  else if (!c.text.empty()) ImGui::TextUnformatted(c.text.c_str());
}

// The input without the part a click picks: what the picture depends on.
std::string picture_key(const Json& input, std::string_view pick) {
  Json key = input;
  if (!pick.empty() && key.is_object()) {
    const Json::json_pointer ptr{std::string(pick)};
    if (key.contains(ptr)) key[ptr.parent_pointer()].erase(ptr.back());
  }
  return key.dump();
}

}  // namespace

SceneCanvas::~SceneCanvas() {
  if (tex_) host_->destroy(tex_);
  if (grey_tex_) host_->destroy(grey_tex_);
}

std::array<float, 4> SceneCanvas::pixel_rect(std::int64_t i, std::int64_t j) const {
  const float sx = (img1_.x - img0_.x) / float(std::max<std::int64_t>(picture_.width, 1));
  const float sy = (img1_.y - img0_.y) / float(std::max<std::int64_t>(picture_.height, 1));
  const float pi = float(i / picture_.scale), pj = float(j / picture_.scale);
  return {img0_.x + sx * pi, img0_.y + sy * pj, img0_.x + sx * (pi + 1), img0_.y + sy * (pj + 1)};
}

void SceneCanvas::refresh(const TraceModel& m) {
  const Algorithm& alg = m.algorithm();
  if (std::string key = picture_key(m.input(), alg.picture.pick); key != key_) {
    key_ = std::move(key);
    try {
      picture_ = alg.picture ? m.run().picture(kMaxSide) : Picture{};  // the parsed input: no re-read
      error_.clear();
    } catch (const std::exception& e) {
      picture_ = {};
      error_ = e.what();
    }
    if (tex_) host_->destroy(tex_), tex_ = nullptr;
    if (grey_tex_) host_->destroy(grey_tex_), grey_tex_ = nullptr;
    if (picture_.width > 0) {
      const std::size_t n = std::size_t(picture_.width * picture_.height);
      std::vector<std::uint32_t> px(n);
      for (std::size_t k = 0; k < n; ++k) px[k] = IM_COL32(picture_.rgb[3 * k], picture_.rgb[3 * k + 1], picture_.rgb[3 * k + 2], 255);
      tex_ = host_->create(int(picture_.width), int(picture_.height));
      host_->update(tex_, 0, 0, int(picture_.width), int(picture_.height), px.data(), int(picture_.width));
      if (picture_.grey.size() == n) {
        for (std::size_t k = 0; k < n; ++k) px[k] = IM_COL32(picture_.grey[k], picture_.grey[k], picture_.grey[k], 255);
        grey_tex_ = host_->create(int(picture_.width), int(picture_.height));
        host_->update(grey_tex_, 0, 0, int(picture_.width), int(picture_.height), px.data(), int(picture_.width));
      }
    }
  }
  if (summarised_ != &m) summarised_ = &m, summary_ = alg.summary_table ? m.run().summary_table(m.trace()) : SummaryTable{};
}

CanvasEvents SceneCanvas::draw(const CanvasInput& in, ImVec2 size) {
  CanvasEvents ev;
  size.x = std::max(size.x, 64.f), size.y = std::max(size.y, 64.f);
  const ImVec2 origin = ImGui::GetCursorScreenPos(), end(origin.x + size.x, origin.y + size.y);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(origin, end, theme::kCanvasBg);
  if (!in.model) return ev;
  keep_ = in.model;
  refresh(*in.model);
  // The image on the left, the side panel (at least 40% of the width) on the right.
  const float side = std::clamp(size.x * 0.45f, std::min(300.f, size.x * 0.6f), 640.f), gap = 8;
  const float aw = size.x - side - gap, ah = size.y;
  const double aspect = picture_.height > 0 ? double(picture_.width) / double(picture_.height) : 4.0 / 3;
  const float w = float(std::min<double>(aw, ah * aspect)), h = float(w / aspect);
  img0_ = ImVec2(origin.x + (aw - w) / 2, origin.y + (ah - h) / 2), img1_ = ImVec2(img0_.x + w, img0_.y + h);
  ImGui::SetCursorScreenPos(img0_);
  ImGui::InvisibleButton("##scene-image", ImVec2(std::max(w, 1.f), std::max(h, 1.f)));
  if (in.hide_sweep) sweep_hidden_note(dl, origin);
  else if (tex_) dl->AddImage(tex_, img0_, img1_);
  if (!error_.empty()) dl->AddText(ImVec2(origin.x + 10, origin.y + 10), theme::kNegative, error_.c_str());
  const Json& input = in.model->input();
  const std::string_view pick = in.model->algorithm().picture.pick;
  const Json::json_pointer at{std::string(pick.empty() ? "/" : pick)};
  const Json picked = !pick.empty() && input.is_object() && input.contains(at) ? input[at] : Json();
  const bool shown = picture_.width > 0 && !in.hide_sweep;
  if (picked.is_array() && picked.size() == 2 && picked[0].is_number_integer() && picked[1].is_number_integer() && shown) {
    const auto r = pixel_rect(picked[0].get<std::int64_t>(), picked[1].get<std::int64_t>());  // the picked pixel, framed
    dl->AddRect(ImVec2(r[0] - 2, r[1] - 2), ImVec2(r[2] + 2, r[3] + 2), IM_COL32(0, 0, 0, 255), 0, 0, 3.f);
    dl->AddRect(ImVec2(r[0] - 1, r[1] - 1), ImVec2(r[2] + 1, r[3] + 1), theme::kCurrentPixel, 0, 0, 1.5f);
  }
  if (ImGui::IsItemHovered() && shown) {
    const ImVec2 mp = ImGui::GetIO().MousePos;
    const std::int64_t pi =
        std::clamp<std::int64_t>(std::int64_t((mp.x - img0_.x) / w * float(picture_.width)), 0, picture_.width - 1);
    const std::int64_t pj =
        std::clamp<std::int64_t>(std::int64_t((mp.y - img0_.y) / h * float(picture_.height)), 0, picture_.height - 1);
    const std::int64_t i = pi * picture_.scale + picture_.scale / 2, j = pj * picture_.scale + picture_.scale / 2;
    const bool picks = in.editable && !pick.empty();
    if (!in.hide_future)
      ImGui::SetTooltip("pixel (%lld, %lld)%s", (long long)i, (long long)j, picks ? "\nclick: trace its history" : "");
    if (ImGui::IsItemClicked() && picks) {
      Json edited = input;
      edited[at] = Json::array({i, j});
      ev.edit = std::move(edited);
    }
  }
  char lines[3][200];
  std::snprintf(lines[0], sizeof lines[0], "%lldx%lld preview in %.2f s", (long long)picture_.width, (long long)picture_.height,
                picture_.seconds);
  std::snprintf(lines[1], sizeof lines[1], "one sample through each pixel's centre");
  std::snprintf(lines[2], sizeof lines[2], "%s", pick.empty() ? "" : "click a pixel: its history");
  if (!in.hide_sweep) status_plate(dl, ImVec2(origin.x + 4, origin.y + 4), lines, !error_.empty());
  ImGui::SetCursorScreenPos(ImVec2(end.x - side, origin.y));
  ImGui::BeginChild("##scene-side", ImVec2(side, size.y), false);
  draw_side(*in.model, in, ev);
  ImGui::EndChild();
  ImGui::SetCursorScreenPos(origin);
  ImGui::Dummy(size);
  corner_label(dl, origin, size, in.label);
  return ev;
}

void SceneCanvas::draw_side(const TraceModel& m, const CanvasInput& in, CanvasEvents& ev) {
  // Quiz mode: the result waits for the last step, the planner's notes for the quiz's end, and
  // the summary shows the rows begun so far.
  const std::size_t step = in.step;
  const bool ended = !in.hide_future || step >= m.last();
  if (const Json* c = ended ? read_result(m, result_reads::scene_colour) : nullptr; c && c->is_array() && c->size() == 3) {
    const std::array<double, 3> rgb{(*c)[0].get<double>(), (*c)[1].get<double>(), (*c)[2].get<double>()};
    ImGui::TextUnformatted("The pixel's colour:");
    ImGui::SameLine();
    char text[96];
    std::snprintf(text, sizeof text, "%.3f %.3f %.3f", rgb[0], rgb[1], rgb[2]);
    colour_cell(rgb, text);
  }
  if (!picture_.notes_title.empty() && !in.hide_sweep && ImGui::CollapsingHeader(picture_.notes_title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
    for (const Picture::Note& n : picture_.notes) {
      if (n.on) ImGui::PushStyleColor(ImGuiCol_Text, *n.on ? theme::kPositive : theme::kZero);
      ImGui::TextWrapped("%s", n.text.c_str());
      if (n.on) ImGui::PopStyleColor();
      if (n.why.empty()) continue;
      ImGui::Indent();
      ImGui::PushStyleColor(ImGuiCol_Text, theme::kDim);
      ImGui::TextWrapped("%s", n.why.c_str());
      ImGui::PopStyleColor();
      ImGui::Unindent();
    }
  }
  if (grey_tex_ && !in.hide_sweep && ImGui::CollapsingHeader(picture_.grey_caption.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
    const float w = std::min(ImGui::GetContentRegionAvail().x, 2.f * float(picture_.width));
    ImGui::Image(grey_tex_, ImVec2(w, w * float(picture_.height) / float(std::max<std::int64_t>(picture_.width, 1))));
  }
  const SummaryTable& t = summary_;
  if (t.columns.empty() || !ImGui::CollapsingHeader(t.title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) return;
  // The current step's row: the innermost one running (or one of this very step).
  int current = -1;
  for (std::size_t k = 0; k < t.rows.size(); ++k)
    if (t.rows[k].step <= step && step <= t.rows[k].end) current = int(k);
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("##summary", int(t.columns.size()), flags)) return;
  for (const std::string& h : t.columns) ImGui::TableSetupColumn(h.c_str());
  ImGui::TableHeadersRow();
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    const SummaryTable::Row& row = t.rows[k];
    const bool later = row.step > step;
    if (later && in.hide_future) continue;
    ImGui::TableNextRow();
    if (int(k) == current) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, IM_COL32(90, 80, 30, 255));
    if (later) ImGui::PushStyleColor(ImGuiCol_Text, theme::kDim);
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      ImGui::TableNextColumn();
      if (c >= row.cells.size()) continue;
      if (c == 0) {  // the row's first cell goes to its step
        const std::string id = row.cells[0].text + "##row" + std::to_string(k);
        if (ImGui::Selectable(id.c_str(), int(k) == current, ImGuiSelectableFlags_SpanAllColumns)) ev.jump_to = row.step;
      } else {
        cell(row.cells[c]);
      }
    }
    if (later) ImGui::PopStyleColor();
  }
  if (t.total && ended) {
    ImGui::TableNextRow();
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      ImGui::TableNextColumn();
      if (c < t.total->cells.size()) cell(t.total->cells[c]);
    }
  }
  ImGui::EndTable();
}

}  // namespace sw::vis
