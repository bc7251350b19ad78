#include "lessons/markdown.hpp"
#include <md4c.h>

namespace sw::vis {
namespace {

struct Builder {
  std::vector<MdBlock> blocks;
  struct List {
    bool ordered;
    unsigned next;
  };
  std::vector<List> lists;
  std::uint8_t style = MdSpan::plain;
  std::string href;
  bool fresh_item = false;  // an item whose first paragraph has not started

  void open(MdBlock::Kind kind, int depth = 0, std::string marker = {}) { blocks.push_back({kind, depth, std::move(marker), {}}); }
  void text(std::string_view t) {
    if (blocks.empty()) open(MdBlock::Kind::paragraph);
    auto& spans = blocks.back().spans;
    if (!spans.empty() && spans.back().style == style && spans.back().href == href) spans.back().text += t;
    else spans.push_back({std::string(t), style, href});
  }
};

std::string_view entity(std::string_view e) {
  if (e == "&amp;") return "&";
  if (e == "&lt;") return "<";
  if (e == "&gt;") return ">";
  if (e == "&quot;") return "\"";
  if (e == "&nbsp;") return "\xC2\xA0";
  return e;
}

int enter_block(MD_BLOCKTYPE type, void* detail, void* user) {
  auto& b = *static_cast<Builder*>(user);
  switch (type) {
    case MD_BLOCK_UL: b.lists.push_back({false, 0}); break;
    case MD_BLOCK_OL: b.lists.push_back({true, static_cast<MD_BLOCK_OL_DETAIL*>(detail)->start}); break;
    case MD_BLOCK_LI: {
      auto& l = b.lists.back();
      b.open(MdBlock::Kind::item, static_cast<int>(b.lists.size()), l.ordered ? std::to_string(l.next++) + "." : "\xE2\x80\xA2");
      b.fresh_item = true;
      break;
    }
    case MD_BLOCK_P:
      if (!b.fresh_item) b.open(MdBlock::Kind::paragraph, static_cast<int>(b.lists.size()));
      b.fresh_item = false;
      break;
    case MD_BLOCK_CODE: b.open(MdBlock::Kind::code); break;
    case MD_BLOCK_H: b.open(MdBlock::Kind::heading, static_cast<int>(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level)); break;
    case MD_BLOCK_QUOTE: b.open(MdBlock::Kind::quote); break;
    default: break;
  }
  return 0;
}

int leave_block(MD_BLOCKTYPE type, void*, void* user) {
  auto& b = *static_cast<Builder*>(user);
  if (type == MD_BLOCK_UL || type == MD_BLOCK_OL) b.lists.pop_back();
  if (type == MD_BLOCK_LI) b.fresh_item = false;
  return 0;
}

int enter_span(MD_SPANTYPE type, void* detail, void* user) {
  auto& b = *static_cast<Builder*>(user);
  if (type == MD_SPAN_STRONG) b.style |= MdSpan::strong;
  if (type == MD_SPAN_EM) b.style |= MdSpan::em;
  if (type == MD_SPAN_CODE) b.style |= MdSpan::code;
  if (type == MD_SPAN_A) {
    b.style |= MdSpan::link;
    const MD_ATTRIBUTE& h = static_cast<MD_SPAN_A_DETAIL*>(detail)->href;
    b.href.assign(h.text, h.size);
  }
  return 0;
}

int leave_span(MD_SPANTYPE type, void*, void* user) {
  auto& b = *static_cast<Builder*>(user);
  if (type == MD_SPAN_STRONG) b.style &= ~MdSpan::strong;
  if (type == MD_SPAN_EM) b.style &= ~MdSpan::em;
  if (type == MD_SPAN_CODE) b.style &= ~MdSpan::code;
  if (type == MD_SPAN_A) b.style &= ~MdSpan::link, b.href.clear();
  return 0;
}

int on_text(MD_TEXTTYPE type, const MD_CHAR* text, MD_SIZE size, void* user) {
  auto& b = *static_cast<Builder*>(user);
  const std::string_view t(text, size);
  if (b.fresh_item) b.fresh_item = false;  // a tight list item's text comes without a paragraph
  switch (type) {
    case MD_TEXT_SOFTBR: b.text(" "); break;
    case MD_TEXT_BR: b.text("\n"); break;
    case MD_TEXT_ENTITY: b.text(entity(t)); break;
    case MD_TEXT_NULLCHAR: b.text("\xEF\xBF\xBD"); break;
    default: b.text(t); break;
  }
  return 0;
}

}  // namespace

std::vector<MdBlock> parse_markdown(std::string_view text) {
  Builder b;
  MD_PARSER p{};
  p.flags = MD_FLAG_NOHTML | MD_FLAG_STRIKETHROUGH | MD_FLAG_PERMISSIVEURLAUTOLINKS;
  p.enter_block = enter_block;
  p.leave_block = leave_block;
  p.enter_span = enter_span;
  p.leave_span = leave_span;
  p.text = on_text;
  md_parse(text.data(), static_cast<MD_SIZE>(text.size()), &p, &b);
  std::erase_if(b.blocks, [](const MdBlock& k) { return k.spans.empty() && k.kind != MdBlock::Kind::item; });
  return b.blocks;
}

}  // namespace sw::vis
