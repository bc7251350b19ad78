#include "flat_json.hpp"
#include <cmath>
#include "core/portable.hpp"

namespace sw {

namespace {
// The root is at depth 1, as check_values::nesting counts: no node deeper than the readers' bound.
constexpr std::size_t kMaxDepth = 64;
// Members per object checked for duplicates pairwise; a larger object is left to parse_json_text.
constexpr std::uint32_t kMaxMembers = 48;
bool is_digit(char c) { return c >= '0' && c <= '9'; }
}  // namespace

bool FlatJson::read(std::string_view text) {
  nodes_.clear();
  text_ = text;
  at_ = 0;
  if (!value(1)) return false;
  skip_space();
  return at_ == text_.size();
}

void FlatJson::skip_space() {
  while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t' || text_[at_] == '\n' || text_[at_] == '\r')) ++at_;
}

void FlatJson::push(Type t, std::string_view text) {
  nodes_.push_back({t, static_cast<std::uint32_t>(nodes_.size() + 1), 0, text});
}

bool FlatJson::string_token() {  // at the opening quote
  const std::size_t start = ++at_;
  for (; at_ < text_.size(); ++at_) {
    const auto c = static_cast<unsigned char>(text_[at_]);
    if (c == '"') {
      push(Type::string, text_.substr(start, at_ - start));
      ++at_;
      return true;
    }
    if (c == '\\' || c < 0x20 || c > 0x7f) return false;  // escapes and UTF-8 are the full parser's
  }
  return false;
}

bool FlatJson::number_token() {
  const std::size_t start = at_;
  auto digits = [&] {
    const std::size_t from = at_;
    while (at_ < text_.size() && is_digit(text_[at_])) ++at_;
    return at_ - from;
  };
  if (at_ < text_.size() && text_[at_] == '-') ++at_;
  const std::size_t whole = digits();
  if (whole == 0 || (whole > 1 && text_[at_ - whole] == '0')) return false;  // no leading zeros
  bool integer = true;
  if (at_ < text_.size() && text_[at_] == '.') {
    ++at_, integer = false;
    if (digits() == 0) return false;
  }
  if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
    ++at_, integer = false;
    if (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) ++at_;
    if (digits() == 0) return false;
  }
  if (integer && whole > 18) return false;  // beyond int64 nlohmann reads it otherwise
  push(integer ? Type::integer : Type::number, text_.substr(start, at_ - start));
  return true;
}

bool FlatJson::value(std::size_t depth) {
  if (depth > kMaxDepth) return false;
  skip_space();
  if (at_ >= text_.size()) return false;
  const std::uint32_t self = static_cast<std::uint32_t>(nodes_.size());
  const char c = text_[at_];
  auto word = [&](std::string_view w, Type t) {
    if (text_.substr(at_, w.size()) != w) return false;
    push(t, text_.substr(at_, w.size()));
    at_ += w.size();
    return true;
  };
  bool ok;
  if (c == '{' || c == '[') {
    const bool object = c == '{';
    push(object ? Type::object : Type::array, {});
    ++at_;
    skip_space();
    std::uint32_t n = 0;
    if (at_ < text_.size() && text_[at_] == (object ? '}' : ']')) {
      ++at_;
    } else {
      for (;;) {
        if (object) {
          skip_space();
          if (at_ >= text_.size() || text_[at_] != '"' || !string_token()) return false;
          skip_space();
          if (at_ >= text_.size() || text_[at_] != ':') return false;
          ++at_;
        }
        if (!value(depth + 1)) return false;
        ++n;
        skip_space();
        if (at_ >= text_.size()) return false;
        if (text_[at_] == ',') { ++at_; continue; }
        if (text_[at_] != (object ? '}' : ']')) return false;
        ++at_;
        break;
      }
    }
    nodes_[self].size = n;
    ok = true;
    if (object && n > 1) {  // duplicate keys: parse_json_text refuses them
      if (n > kMaxMembers) return false;
      for (std::uint32_t a = first_member(self), i = 0; i < n; a = nodes_[a + 1].end, ++i)
        for (std::uint32_t b = nodes_[a + 1].end, j = i + 1; j < n; b = nodes_[b + 1].end, ++j)
          if (nodes_[a].text == nodes_[b].text) return false;
    }
  } else if (c == '"') {
    ok = string_token();
  } else if (c == '-' || is_digit(c)) {
    ok = number_token();
  } else {
    ok = word("true", Type::boolean) || word("false", Type::boolean) || word("null", Type::null);
  }
  if (!ok) return false;
  nodes_[self].end = static_cast<std::uint32_t>(nodes_.size());  // a container's, after its elements
  return true;
}

std::optional<std::uint32_t> FlatJson::member(std::uint32_t o, std::string_view name) const {
  std::uint32_t k = first_member(o);
  for (std::uint32_t i = 0; i < nodes_[o].size; ++i, k = next_member(k))
    if (nodes_[k].text == name) return k + 1;
  return std::nullopt;
}

std::optional<double> FlatJson::number(std::uint32_t i) const {
  const std::string_view t = nodes_[i].text;
  double d = 0;
  if (!parse_double(t, d) || !std::isfinite(d)) return std::nullopt;
  return d;
}

}  // namespace sw
