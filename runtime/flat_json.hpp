// A JSON reader for `check`'s fast path: one line read into a flat array of nodes that point into
// its text, reused from line to line, so reading a step allocates nothing. It reads a strict subset
// of what parse_json_text takes and refuses (returns false on) everything else: escapes and bytes
// above 0x7f in strings, duplicate keys, integers of more than 18 digits, nesting deeper than the
// readers' bound. A refused line is read again by parse_json_text, which names its problem.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace sw {

class FlatJson {
 public:
  enum class Type : std::uint8_t { null, boolean, integer, number, string, array, object };
  struct Node {
    Type type;
    std::uint32_t end;   // the index one past this node's subtree
    std::uint32_t size;  // elements of an array, members of an object
    std::string_view text;  // a scalar's text (a string's without its quotes)
  };
  // Reads `text` (which must outlive the nodes); false if it is not in the subset.
  bool read(std::string_view text);
  const Node& operator[](std::uint32_t i) const { return nodes_[i]; }
  static constexpr std::uint32_t root = 0;

  // An object's members as (key, value) node indices: the key at i, its value at i + 1.
  // The first member of object `o`, and the member after the one whose key is at `key`.
  std::uint32_t first_member(std::uint32_t o) const { return o + 1; }
  std::uint32_t next_member(std::uint32_t key) const { return nodes_[key + 1].end; }
  // The value of `o`'s member named `name`, if it has one (`o` must be an object).
  std::optional<std::uint32_t> member(std::uint32_t o, std::string_view name) const;
  // An array's elements: the first, and the one after element `e`.
  std::uint32_t first_element(std::uint32_t a) const { return a + 1; }
  std::uint32_t next_element(std::uint32_t e) const { return nodes_[e].end; }
  // A number's value (an integer's rounded as nlohmann's get<double>() rounds it); nothing if it
  // is out of double's range.
  std::optional<double> number(std::uint32_t i) const;

 private:
  bool value(std::size_t depth);
  bool string_token();
  bool number_token();
  void skip_space();
  void push(Type t, std::string_view text);  // a node whose subtree is itself
  std::vector<Node> nodes_;
  std::string_view text_;
  std::size_t at_ = 0;
};

}  // namespace sw
