// The listing: the algorithm's pseudocode with the current step's line highlighted.
#include "panels/panels.hpp"

namespace sw::vis {

void ListingPanel::draw(const Session& s, const Chrome& c, const PanelRect& r) {
  place_next(r.pos, r.size);
  // A step inside a nested call shows the callee's listing (its steps' lines are in it).
  const Algorithm* alg = s.algorithm();
  const TraceModel* m = s.model(0);
  const std::size_t step = s.shown_step();
  const StepRecord* st = alg && m ? &m->trace().at(step) : nullptr;
  const Listing* listing = alg ? &alg->listing : nullptr;
  std::string title = alg ? std::string(alg->listing.title) : std::string("Listing");
  if (st && st->scope) {
    listing = &m->trace().scope_listing(st->scope);
    title = std::string(listing->title) + "  (called by " + std::string(alg->listing.title) + ")";
  }
  title += "###Listing";
  ImGui::Begin(title.c_str(), nullptr, kPanelFlags);
  highlighted_ = 0;
  rows_.clear();
  if (!alg || !m) {
    ImGui::End();
    return;
  }
  const std::uint32_t line = st->line;
  highlighted_ = line;
  ImGui::PushFont(c.fonts.mono);
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(ImGui::GetStyle().ItemSpacing.x, 3));
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const auto& lines = listing->lines;
  const float number_w = ImGui::CalcTextSize("00 ").x;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const bool current = i + 1 == line;
    // Code, then its "-- comment": on the same row when it fits, else wrapped below, dimmed.
    std::string_view text = lines[i].text, comment;
    if (auto c = text.find("--"); c != std::string_view::npos) {
      comment = text.substr(c);
      text = text.substr(0, c);
      while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
    }
    dl->ChannelsSplit(2);
    dl->ChannelsSetCurrent(1);
    const ImVec2 top = ImGui::GetCursorScreenPos();
    ImGui::TextColored(current ? ImVec4(1, 1, 1, 1) : theme::kDim, "%2zu", i + 1);
    // Leading spaces become an indent, so that wrapped code stays under its own first line.
    std::size_t indent = 0;
    while (indent < text.size() && text[indent] == ' ') ++indent;
    text.remove_prefix(indent);
    ImGui::SameLine(number_w + ImGui::GetStyle().WindowPadding.x + float(indent) * ImGui::CalcTextSize(" ").x);
    const ImVec4 code_col = current ? ImVec4(1, 1, 1, 1) : ImVec4(0.80f, 0.82f, 0.86f, 1);
    ImGui::PushStyleColor(ImGuiCol_Text, code_col);
    ImGui::PushTextWrapPos(0);  // long code lines wrap under themselves, not under the number
    ImGui::TextUnformatted(text.data(), text.data() + text.size());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
    if (!comment.empty()) {
      const float room = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x - ImGui::GetItemRectMax().x;
      const ImVec4 comment_col = current ? ImVec4(0.85f, 0.88f, 1, 1) : ImVec4(0.50f, 0.53f, 0.60f, 1);
      if (ImGui::CalcTextSize(comment.data(), comment.data() + comment.size()).x + 16 < room) {
        ImGui::SameLine(0, 16);
      } else {
        ImGui::SetCursorPosX(ImGui::GetCursorPosX() + number_w + 2 * ImGui::CalcTextSize(" ").x);
      }
      ImGui::PushStyleColor(ImGuiCol_Text, comment_col);
      ImGui::PushTextWrapPos(0);
      ImGui::TextUnformatted(comment.data(), comment.data() + comment.size());
      ImGui::PopTextWrapPos();
      ImGui::PopStyleColor();
    }
    const float bottom = ImGui::GetCursorScreenPos().y;
    rows_.push_back({top.x, top.y, bottom});
    dl->ChannelsSetCurrent(0);
    if (current) {
      dl->AddRectFilled(ImVec2(top.x - 4, top.y - 2), ImVec2(top.x + ImGui::GetContentRegionAvail().x + 4, bottom - 2), theme::kLineHighlight, 2);
      // Centre the line for two frames after the step changes: the first frame of a window clamps
      // the scroll to a content height it has not measured yet.
      if (scrolled_to_ != step) scrolled_to_ = step, scroll_frames_ = 2;
      if (scroll_frames_ > 0) ImGui::SetScrollFromPosY(top.y - ImGui::GetWindowPos().y, 0.5f), --scroll_frames_;
    }
    dl->ChannelsMerge();
  }
  ImGui::PopStyleVar();
  ImGui::PopFont();
  content_h_ = ImGui::GetCursorPosY() + ImGui::GetStyle().WindowPadding.y;
  ImGui::End();
}

}  // namespace sw::vis
