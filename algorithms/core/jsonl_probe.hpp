// Streams each step as one JSON line, written in blocks as the run goes (the rest on finish()),
// so memory stays flat for any trace length. Format: docs/trace-format.md.
#pragma once
#include <array>
#include <cstring>
#include <exception>
#include <initializer_list>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>
#include "core/emitters.hpp"
#include "core/number.hpp"
#include "core/step.hpp"
#include "core/vec.hpp"

namespace sw {

// The text goes straight into two buffers (this step's variables, its geometry) with no temporary
// strings, and complete lines are written in blocks of about 64 KiB.
template <class Num> class JsonlProbe : public GeometryEmitters<JsonlProbe<Num>, Num> {
 public:
  static constexpr bool on = true;

  explicit JsonlProbe(std::ostream& out) : out_(out) {}
  JsonlProbe(const JsonlProbe&) = delete;
  // Writes what is pending, unless an exception is unwinding the run (the output is abandoned
  // then, and the stream may be what threw).
  ~JsonlProbe() {
    if (std::uncaught_exceptions() > 0) return;
    try {
      finish();
    } catch (...) {}
  }

  JsonlProbe& step(std::uint32_t line, StepKind kind) {
    close_line();
    if (text_.size() >= kBlock) write_pending();
    open_ = true;
    text_ += "{\"step\":";
    append_json(text_, static_cast<std::int64_t>(count_++));
    text_ += ",\"line\":";
    append_json(text_, static_cast<std::int64_t>(line));
    text_ += ",\"kind\":\"";
    text_ += kind_name(kind);
    if (!scopes_.empty()) {  // a nested listing: "in" names the callee whose listing `line` is in
      text_ += "\",\"in\":\"";
      text_ += scopes_.back();
    }
    text_ += "\",\"vars\":{";
    geo_.clear();
    first_var_ = true;
    return *this;
  }
  JsonlProbe& num(const char* name, const Num& v) {
    number(var(name), v);
    return *this;
  }
  JsonlProbe& idx(const char* name, std::int64_t v) {
    append_json(var(name), v);
    return *this;
  }
  JsonlProbe& vec(const char* name, const Vec2<Num>& v) { return values(var(name), {v.x, v.y}, "[", "]"); }
  JsonlProbe& vec(const char* name, const Vec3<Num>& v) { return values(var(name), {v.x, v.y, v.z}, "[", "]"); }
  JsonlProbe& colour(const char* name, const Vec3<Num>& c) {
    return values(var(name), {c.x, c.y, c.z}, "{\"rgb\":[", "]}");
  }
  JsonlProbe& list(const char* name, std::span<const Num> xs) { return list_of(name, xs); }
  JsonlProbe& ilist(const char* name, std::span<const std::int64_t> xs) { return list_of(name, xs); }
  JsonlProbe& pixel(Pixel p) { return igeo(GeoKind::pixel, p.x, p.y); }
  JsonlProbe& span(std::int64_t j, std::int64_t i0, std::int64_t i1) { return igeo(GeoKind::span, j, i0, i1); }
  template <class... I> JsonlProbe& igeo(GeoKind kind, I... values) {
    open_geo(kind);
    bool first = true;
    ((geo_ += (first ? "" : ","), append_json(geo_, static_cast<std::int64_t>(values)), first = false), ...);
    geo_ += "]}";
    return *this;
  }
  JsonlProbe& geo_list(GeoKind kind, std::span<const Vec2<Num>> points) {
    open_geo(kind);
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (i) geo_ += ',';
      number(geo_, points[i].x);
      geo_ += ',';
      number(geo_, points[i].y);
    }
    geo_ += "]}";
    return *this;
  }
  template <class... V> JsonlProbe& geo(GeoKind kind, const V&... values) {
    open_geo(kind);
    bool first = true;
    ((geo_ += (first ? "" : ","), number(geo_, Num(values)), first = false), ...);
    geo_ += "]}";
    return *this;
  }

  // Modifiers of the item just emitted (probe.hpp): written as its "label", "life" and "value".
  JsonlProbe& label(const char* text) {
    item_member("label") += '"';
    geo_ += text;
    geo_ += "\"}";
    return *this;
  }
  JsonlProbe& keep() { return life(Life::keep); }
  JsonlProbe& replace() { return life(Life::replace); }
  JsonlProbe& life(Life l) {
    item_member("life") += '"';
    geo_ += life_name(l);
    geo_ += "\"}";
    return *this;
  }
  JsonlProbe& value(const Num& v) {
    number(item_member("value"), v);
    geo_ += '}';
    return *this;
  }

  void enter(std::string_view id, const Listing&) { scopes_.push_back(id); }
  void leave() { scopes_.pop_back(); }

  // Ends the last step's line and writes every pending line to the stream.
  void finish() {
    close_line();
    write_pending();
  }
  std::uint64_t count() const { return count_; }

 private:
  static constexpr std::size_t kBlock = std::size_t{1} << 16;

  void close_line() {
    if (!open_) return;
    text_ += "},\"geo\":[";
    text_ += geo_;
    text_ += "]}\n";
    open_ = false;
  }
  void write_pending() {
    out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
    text_.clear();
  }
  // Starts variable `name` and returns the buffer its value goes to.
  std::string& var(const char* name) {
    if (!first_var_) text_ += ',';
    first_var_ = false;
    text_ += '"';
    text_ += name;
    text_ += "\":";
    return text_;
  }
  JsonlProbe& values(std::string& out, std::initializer_list<Num> xs, const char* open, const char* close) {
    out += open;
    bool first = true;
    for (const Num& x : xs) {
      if (!first) out += ',';
      number(out, x);
      first = false;
    }
    out += close;
    return *this;
  }
  template <class T> JsonlProbe& list_of(const char* name, std::span<const T> xs) {
    if (xs.size() > kMaxListLength) throw std::length_error("a list variable of more than 64 entries");
    std::string& out = var(name);
    out += '[';
    for (std::size_t i = 0; i < xs.size(); ++i) {
      if (i) out += ',';
      if constexpr (std::is_same_v<T, Num>) number(out, xs[i]);
      else append_json(out, xs[i]);
    }
    out += ']';
    return *this;
  }
  // A number's text. Shortest round-trip formatting of a double takes 60-100 ns, most of a step's
  // cost, and a step often writes a value twice (a variable, then the point made of it): the last
  // few doubles' texts are kept and reused when the same bits come again.
  void number(std::string& out, const Num& x) {
    if constexpr (std::is_same_v<Num, double> || std::is_same_v<Num, float>) {
      const double d = x;
      std::uint64_t bits;
      std::memcpy(&bits, &d, sizeof bits);
      for (const Memo& m : memo_)
        if (m.length && m.bits == bits) {
          out.append(m.text, m.length);
          return;
        }
      const std::size_t before = out.size();
      append_json(out, x);
      Memo& m = memo_[next_memo_++ % memo_.size()];
      const std::size_t n = out.size() - before;
      m.bits = bits, m.length = n <= sizeof m.text ? static_cast<std::uint8_t>(n) : 0;
      if (m.length) std::memcpy(m.text, out.data() + before, n);
    } else {
      append_json(out, x);
    }
  }
  // Reopens the last item's object (it ends in '}') for one more member; the caller writes the
  // member's value and closes the object again.
  std::string& item_member(const char* key) {
    geo_.pop_back();
    geo_ += ",\"";
    geo_ += key;
    geo_ += "\":";
    return geo_;
  }
  void open_geo(GeoKind kind) {
    if (!geo_.empty()) geo_ += ',';
    geo_ += "{\"";
    geo_ += geo_name(kind);
    geo_ += "\":[";
  }

  std::ostream& out_;
  std::vector<std::string_view> scopes_;
  std::string text_;  // complete lines not yet written, then the open step's line up to its variables
  std::string geo_;   // the open step's geometry items
  struct Memo {
    std::uint64_t bits = 0;
    std::uint8_t length = 0;  // 0: empty
    char text[27];            // a double's shortest text is at most 24 characters; quoted NaN 5
  };
  std::array<Memo, 4> memo_{};
  std::uint32_t next_memo_ = 0;
  std::uint64_t count_ = 0;
  bool open_ = false, first_var_ = true;
};

}  // namespace sw
