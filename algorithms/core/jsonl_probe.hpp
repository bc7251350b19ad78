// Streams each step as one JSON line as soon as the next one starts (or on finish()), so memory
// stays flat for any trace length. Format: docs/trace-format.md.
#pragma once
#include <exception>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>
#include "core/number.hpp"
#include "core/step.hpp"
#include "core/vec.hpp"

namespace sw {

template <class Num> class JsonlProbe {
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
    } catch (...) {
    }
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
  JsonlProbe& vec(const char* name, const Vec2<Num>& v) { return add_var(name, '[' + json_value(v.x) + ',' + json_value(v.y) + ']'); }
  JsonlProbe& vec(const char* name, const Vec3<Num>& v) { return add_var(name, '[' + json_value(v.x) + ',' + json_value(v.y) + ',' + json_value(v.z) + ']'); }
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
  JsonlProbe& point(const Vec2<Num>& p) { return geo(GeoKind::point2, p.x, p.y); }
  JsonlProbe& point(const Vec3<Num>& p) { return geo(GeoKind::point3, p.x, p.y, p.z); }

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
