// The listing: the algorithm's pseudocode with the current step's line highlighted.
#include "panels/app.hpp"

namespace sw::vis {

void App::draw_listing(ImVec2 pos, ImVec2 size) {
  place_next(pos, size);
  // A step inside a nested call shows the callee's listing (its steps' lines are in it).
  const StepRecord* st = alg_ && a_ ? &a_->trace().at(step_) : nullptr;
  const Listing* listing = alg_ ? &alg_->listing : nullptr;
  std::string title = alg_ ? std::string(alg_->listing.title) : std::string("Listing");
  if (st && st->scope) {
    listing = &a_->trace().scope_listing(st->scope);
    title = std::string(listing->title) + "  (called by " + std::string(alg_->listing.title) + ")";
  }
  title += "###Listing";
  ImGui::Begin(title.c_str(), nullptr, kPanelFlags);
  highlighted_line_ = 0;
  listing_rows_.clear();
  if (!alg_ || !a_) {
    ImGui::End();
    return;
  }
  const std::uint32_t line = st->line;
  highlighted_line_ = line;
  ImGui::PushFont(fonts_.mono);
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
    listing_rows_.push_back({top.x, top.y, bottom});
    dl->ChannelsSetCurrent(0);
    if (current) {
      dl->AddRectFilled(ImVec2(top.x - 4, top.y - 2), ImVec2(top.x + ImGui::GetContentRegionAvail().x + 4, bottom - 2), theme::kLineHighlight, 2);
      // Centre the line for two frames after the step changes: the first frame of a window clamps
      // the scroll to a content height it has not measured yet.
      if (listing_scrolled_to_ != step_) listing_scrolled_to_ = step_, listing_scroll_frames_ = 2;
      if (listing_scroll_frames_ > 0) ImGui::SetScrollFromPosY(top.y - ImGui::GetWindowPos().y, 0.5f), --listing_scroll_frames_;
    }
    dl->ChannelsMerge();
  }
  ImGui::PopStyleVar();
  ImGui::PopFont();
  listing_content_h_ = ImGui::GetCursorPosY() + ImGui::GetStyle().WindowPadding.y;
  ImGui::End();
}

}  // namespace sw::vis
