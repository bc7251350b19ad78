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

// A colour as a swatch, then (with numbers) its three components; the swatch's tooltip has them.
void colour_cell(const std::array<double, 3>& c, bool numbers = true) {
  const ImVec2 p = ImGui::GetCursorScreenPos();
  const float h = ImGui::GetTextLineHeight();
  ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, p.y + 2), ImVec2(p.x + h - 4, p.y + h - 2), rgb_u32(c));
  ImGui::Dummy(ImVec2(h - 2, h));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("rgb(%.6g, %.6g, %.6g)", c[0], c[1], c[2]);
  if (!numbers) return;
  ImGui::SameLine();
  ImGui::Text("%.3f %.3f %.3f", c[0], c[1], c[2]);
}

}  // namespace

SceneCanvas::~SceneCanvas() {
  if (tex_) host_->destroy(tex_);
}

std::array<float, 4> SceneCanvas::pixel_rect(std::int64_t i, std::int64_t j) const {
  const float sx = (img1_.x - img0_.x) / float(std::max<std::int64_t>(preview_.width, 1));
  const float sy = (img1_.y - img0_.y) / float(std::max<std::int64_t>(preview_.height, 1));
  const float pi = float(i / preview_.scale), pj = float(j / preview_.scale);
  return {img0_.x + sx * pi, img0_.y + sy * pj, img0_.x + sx * (pi + 1), img0_.y + sy * (pj + 1)};
}

void SceneCanvas::refresh(const TraceModel& m) {
  Json scene_key = m.input();
  if (scene_key.is_object()) scene_key.erase("pixel");
  if (std::string key = scene_key.dump(); key != key_) {
    key_ = std::move(key);
    try {
      preview_ = tracer::render_preview(tracer::parse_history_input(m.input()), kMaxSide);
      error_.clear();
    } catch (const std::exception& e) {
      preview_ = {};
      error_ = e.what();
    }
    if (tex_) host_->destroy(tex_), tex_ = nullptr;
    if (preview_.width > 0) {
      std::vector<std::uint32_t> px(preview_.rgb.size() / 3);
      for (std::size_t k = 0; k < px.size(); ++k) px[k] = IM_COL32(preview_.rgb[3 * k], preview_.rgb[3 * k + 1], preview_.rgb[3 * k + 2], 255);
      tex_ = host_->create(int(preview_.width), int(preview_.height));
      host_->update(tex_, 0, 0, int(preview_.width), int(preview_.height), px.data(), int(preview_.width));
    }
  }
  if (treed_ != &m) treed_ = &m, tree_ = tracer::ray_tree(m.trace());
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
  const double aspect = preview_.height > 0 ? double(preview_.width) / double(preview_.height) : 4.0 / 3;
  const float w = float(std::min<double>(aw, ah * aspect)), h = float(w / aspect);
  img0_ = ImVec2(origin.x + (aw - w) / 2, origin.y + (ah - h) / 2), img1_ = ImVec2(img0_.x + w, img0_.y + h);
  ImGui::SetCursorScreenPos(img0_);
  ImGui::InvisibleButton("##scene-image", ImVec2(std::max(w, 1.f), std::max(h, 1.f)));
  if (tex_) dl->AddImage(tex_, img0_, img1_);
  if (!error_.empty()) dl->AddText(ImVec2(origin.x + 10, origin.y + 10), theme::kNegative, error_.c_str());
  const Json& input = in.model->input();
  const auto pixel = input.contains("pixel") ? input["pixel"] : Json();
  if (pixel.is_array() && pixel.size() == 2 && preview_.width > 0) {  // the traced pixel, framed
    const auto r = pixel_rect(pixel[0].get<std::int64_t>(), pixel[1].get<std::int64_t>());
    dl->AddRect(ImVec2(r[0] - 2, r[1] - 2), ImVec2(r[2] + 2, r[3] + 2), IM_COL32(0, 0, 0, 255), 0, 0, 3.f);
    dl->AddRect(ImVec2(r[0] - 1, r[1] - 1), ImVec2(r[2] + 1, r[3] + 1), theme::kCurrentPixel, 0, 0, 1.5f);
  }
  if (ImGui::IsItemHovered() && preview_.width > 0) {
    const ImVec2 mp = ImGui::GetIO().MousePos;
    const std::int64_t pi = std::clamp<std::int64_t>(std::int64_t((mp.x - img0_.x) / w * float(preview_.width)), 0, preview_.width - 1);
    const std::int64_t pj = std::clamp<std::int64_t>(std::int64_t((mp.y - img0_.y) / h * float(preview_.height)), 0, preview_.height - 1);
    const std::int64_t i = pi * preview_.scale + preview_.scale / 2, j = pj * preview_.scale + preview_.scale / 2;
    if (!in.hide_future) ImGui::SetTooltip("pixel (%lld, %lld)%s", (long long)i, (long long)j, in.editable ? "\nclick: trace its history" : "");
    if (ImGui::IsItemClicked() && in.editable) ev.edit = tracer::with_pixel(input, i, j);
  }
  char lines[3][200];
  std::snprintf(lines[0], sizeof lines[0], "%lldx%lld preview in %.2f s", (long long)preview_.width, (long long)preview_.height, preview_.seconds);
  std::snprintf(lines[1], sizeof lines[1], "one sample through each pixel's centre");
  std::snprintf(lines[2], sizeof lines[2], "click a pixel: its history");
  status_plate(dl, ImVec2(origin.x + 4, origin.y + 4), lines, !error_.empty());
  ImGui::SetCursorScreenPos(ImVec2(end.x - side, origin.y));
  ImGui::BeginChild("##scene-side", ImVec2(side, size.y), false);
  draw_side(*in.model, in.step, ev);
  ImGui::EndChild();
  ImGui::SetCursorScreenPos(origin);
  ImGui::Dummy(size);
  corner_label(dl, origin, size, in.label);
  return ev;
}

void SceneCanvas::draw_side(const TraceModel& m, std::size_t step, CanvasEvents& ev) {
  if (const Json* r = read_result(m, result_reads::scene_colour); r && r->is_array() && r->size() == 3) {
    const std::array<double, 3> c{(*r)[0].get<double>(), (*r)[1].get<double>(), (*r)[2].get<double>()};
    ImGui::TextUnformatted("The pixel's colour:");
    ImGui::SameLine();
    colour_cell(c);
  }
  if (ImGui::CollapsingHeader("Planner", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (preview_.plan.all_effects) ImGui::TextWrapped("All effects on (all_effects): nothing planned away.");
    for (const tracer::Decision& d : preview_.plan.decisions) {
      ImGui::PushStyleColor(ImGuiCol_Text, d.on ? theme::kPositive : theme::kZero);
      ImGui::TextWrapped("%s for %s: %s", d.effect.c_str(), d.subject.c_str(), d.on ? "on" : "off");
      ImGui::PopStyleColor();
      ImGui::Indent();
      ImGui::PushStyleColor(ImGuiCol_Text, theme::kDim);
      ImGui::TextWrapped("%s", d.reason.c_str());
      ImGui::PopStyleColor();
      ImGui::Unindent();
    }
  }
  if (!ImGui::CollapsingHeader("Ray tree", ImGuiTreeNodeFlags_DefaultOpen)) return;
  // The current step's ray: the innermost one running (or the shadow ray of this very step).
  int current = -1;
  for (std::size_t k = 0; k < tree_.size(); ++k)
    if (tree_[k].step <= step && step <= tree_[k].end) current = int(k);
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;
  if (!ImGui::BeginTable("##rays", 6, flags)) return;
  for (const char* h : {"ray", "depth", "kind", "weight", "found", "share"}) ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  for (std::size_t k = 0; k < tree_.size(); ++k) {
    const tracer::RayNode& n = tree_[k];
    const bool later = n.step > step, shadow = n.kind == tracer::RayNode::Kind::shadow;
    ImGui::TableNextRow();
    if (int(k) == current) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, IM_COL32(90, 80, 30, 255));
    if (later) ImGui::PushStyleColor(ImGuiCol_Text, theme::kDim);
    ImGui::TableNextColumn();
    char id[48];
    std::snprintf(id, sizeof id, "%zu##ray%zu", k, k);
    if (ImGui::Selectable(id, int(k) == current, ImGuiSelectableFlags_SpanAllColumns)) ev.jump_to = n.step;
    ImGui::TableNextColumn();
    ImGui::Text("%d", n.depth);
    ImGui::TableNextColumn();
    if (shadow) ImGui::Text("shadow %lld: %s", (long long)n.light, n.hit ? "blocked" : "lit");
    else ImGui::Text("%s%s", std::string(tracer::kind_name(n.kind)).c_str(), n.hit ? "" : " (miss)");
    ImGui::TableNextColumn();
    ImGui::Text("%.4g", n.weight);
    ImGui::TableNextColumn();
    if (!shadow && n.returned) colour_cell(n.local, false);
    ImGui::TableNextColumn();
    if (!shadow && n.returned) colour_cell(n.added);
    if (later) ImGui::PopStyleColor();
  }
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted("sum");
  for (int c = 0; c < 4; ++c) ImGui::TableNextColumn();
  ImGui::TableNextColumn();
  colour_cell(tracer::ray_tree_sum(tree_));
  ImGui::EndTable();
}

}  // namespace sw::vis
