// Narration Markdown as blocks of styled spans, parsed by md4c (CommonMark), for panels that draw
// text themselves. The HTML export uses md4c-html on the same text.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sw::vis {

struct MdSpan {
  enum Style : std::uint8_t { plain = 0, strong = 1, em = 2, code = 4, link = 8 };
  std::string text;
  std::uint8_t style = plain;
  std::string href;  // for links
};

struct MdBlock {
  enum class Kind { paragraph, item, code, heading, quote } kind = Kind::paragraph;
  int depth = 0;       // list nesting (items) or heading level
  std::string marker;  // an item's bullet or number ("3.")
  std::vector<MdSpan> spans;
};

std::vector<MdBlock> parse_markdown(std::string_view text);

}  // namespace sw::vis
