// Streams each step as one JSON line as soon as the next one starts (or on finish()), so memory
// stays flat for any trace length. Format: docs/trace-format.md.
#pragma once
#include <exception>
#include <ostream>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>
#include "core/emitters.hpp"
#include "core/number.hpp"
#include "core/step.hpp"
#include "core/vec.hpp"

namespace sw {

template <class Num> class JsonlProbe : public GeometryEmitters<JsonlProbe<Num>, Num> {
 public:
  static constexpr bool on = true;

  explicit JsonlProbe(std::ostream& out) : out_(out) {}
  JsonlProbe(const JsonlProbe&) = delete;
  // Flushes the last step, unless an exception is unwinding the run (the output is abandoned
  // then, and the stream may be what threw).
  ~JsonlProbe() {
    if (std::uncaught_exceptions() > 0) return;
    try {
      finish();
    } catch (...) {}
  }

  JsonlProbe& step(std::uint32_t line, StepKind kind) {
    finish();
    open_ = true;
    line_ = "{\"step\":" + std::to_string(count_++) + ",\"line\":" + std::to_string(line) + ",\"kind\":\"";
    line_ += kind_name(kind);
    if (!scopes_.empty()) {  // a nested listing: "in" names the callee whose listing `line` is in
      line_ += "\",\"in\":\"";
      line_ += scopes_.back();
    }
    line_ += "\",\"vars\":{";
    geo_.clear();
    first_var_ = true;
    return *this;
  }
  JsonlProbe& num(const char* name, const Num& v) { return add_var(name, json_value(v)); }
  JsonlProbe& idx(const char* name, std::int64_t v) { return add_var(name, std::to_string(v)); }
  JsonlProbe& vec(const char* name, const Vec2<Num>& v) {
    return add_var(name, '[' + json_value(v.x) + ',' + json_value(v.y) + ']');
  }
  JsonlProbe& vec(const char* name, const Vec3<Num>& v) {
    return add_var(name, '[' + json_value(v.x) + ',' + json_value(v.y) + ',' + json_value(v.z) + ']');
  }
  JsonlProbe& colour(const char* name, const Vec3<Num>& c) {
    return add_var(name, "{\"rgb\":[" + json_value(c.x) + ',' + json_value(c.y) + ',' + json_value(c.z) + "]}");
  }
  JsonlProbe& list(const char* name, std::span<const Num> xs) {
    return add_var(name, json_list(xs, [](const Num& x) { return json_value(x); }));
  }
  JsonlProbe& ilist(const char* name, std::span<const std::int64_t> xs) {
    return add_var(name, json_list(xs, [](std::int64_t x) { return std::to_string(x); }));
  }
  JsonlProbe& pixel(Pixel p) { return igeo(GeoKind::pixel, p.x, p.y); }
  JsonlProbe& span(std::int64_t j, std::int64_t i0, std::int64_t i1) { return igeo(GeoKind::span, j, i0, i1); }
  template <class... I> JsonlProbe& igeo(GeoKind kind, I... values) {
    open_geo(kind);
    bool first = true;
    ((geo_ += (first ? "" : ","), geo_ += std::to_string(static_cast<std::int64_t>(values)), first = false), ...);
    geo_ += "]}";
    return *this;
  }
  JsonlProbe& geo_list(GeoKind kind, std::span<const Vec2<Num>> points) {
    open_geo(kind);
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (i) geo_ += ',';
      geo_ += json_value(points[i].x);
      geo_ += ',';
      geo_ += json_value(points[i].y);
    }
    geo_ += "]}";
    return *this;
  }
  template <class... V> JsonlProbe& geo(GeoKind kind, const V&... values) {
    open_geo(kind);
    bool first = true;
    ((geo_ += (first ? "" : ","), geo_ += json_value(Num(values)), first = false), ...);
    geo_ += "]}";
    return *this;
  }

  // Modifiers of the item just emitted (probe.hpp): written as its "label", "life" and "value".
  JsonlProbe& label(const char* text) { return item_member("label", '"' + std::string(text) + '"'); }
  JsonlProbe& keep() { return life(Life::keep); }
  JsonlProbe& replace() { return life(Life::replace); }
  JsonlProbe& life(Life l) { return item_member("life", '"' + std::string(life_name(l)) + '"'); }
  JsonlProbe& value(const Num& v) { return item_member("value", json_value(v)); }

  void enter(std::string_view id, const Listing&) { scopes_.push_back(id); }
  void leave() { scopes_.pop_back(); }

  void finish() {
    if (!open_) return;
    line_ += "},\"geo\":[";
    line_ += geo_;
    line_ += "]}\n";
    out_.write(line_.data(), static_cast<std::streamsize>(line_.size()));
    open_ = false;
  }
  std::uint64_t count() const { return count_; }

 private:
  JsonlProbe& add_var(const char* name, const std::string& text) {
    if (!first_var_) line_ += ',';
    first_var_ = false;
    line_ += '"';
    line_ += name;
    line_ += "\":";
    line_ += text;
    return *this;
  }
  template <class T, class F> static std::string json_list(std::span<const T> xs, F text) {
    if (xs.size() > kMaxListLength) throw std::length_error("a list variable of more than 64 entries");
    std::string t = "[";
    for (std::size_t i = 0; i < xs.size(); ++i) t += (i ? "," : "") + text(xs[i]);
    return t + ']';
  }
  // Reopens the last item's object (it ends in '}') for one more member.
  JsonlProbe& item_member(const char* key, const std::string& text) {
    geo_.pop_back();
    geo_ += ",\"";
    geo_ += key;
    geo_ += "\":";
    geo_ += text;
    geo_ += '}';
    return *this;
  }
  void open_geo(GeoKind kind) {
    if (!geo_.empty()) geo_ += ',';
    geo_ += "{\"";
    geo_ += geo_name(kind);
    geo_ += "\":[";
  }

  std::ostream& out_;
  std::vector<std::string_view> scopes_;
  std::string line_, geo_;
  std::uint64_t count_ = 0;
  bool open_ = false, first_var_ = true;
};

}  // namespace sw
