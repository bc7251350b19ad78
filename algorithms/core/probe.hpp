// Probes: where an algorithm's steps go.
//  - NoProbe: nothing. Algorithms guard every step with `if constexpr (Probe::on)`, so no argument
//    is evaluated and the untraced code is the plain loop.
//  - Recorder<Num>: in memory, random access (the app steps backward by indexing).
//  - JsonlProbe<Num> (jsonl_probe.hpp): streams JSON lines; memory stays flat.
#pragma once
#include <cstdint>
#include <string>
#include <vector>
#include "core/number.hpp"
#include "core/step.hpp"
#include "core/vec.hpp"

namespace sw {

struct NoProbe {
  static constexpr bool on = false;
};

// Steps as stored: ranges into the shared variable and geometry arrays.
struct StepRecord {
  std::uint32_t line;
  StepKind kind;
  std::uint32_t var_begin, var_end, geo_begin, geo_end;
};
struct VarRecord {
  const char* name;     // a string literal from the algorithm
  std::uint32_t slot;   // into the number or the integer store
  bool is_int;
};
struct GeoRecord {
  GeoKind kind;
  std::uint32_t slot;   // first of geo_arity(kind) values (integers for pixels)
};

// The number-independent part of a recorded trace, with virtual access to the numbers. The
// visualizer and `check` read traces through this.
class TraceView {
 public:
  virtual ~TraceView() = default;
  virtual Numeric numeric() const = 0;
  virtual double num_double(std::uint32_t slot) const = 0;
  virtual std::string num_text(std::uint32_t slot) const = 0;  // lossless

  std::size_t size() const { return steps_.size(); }
  const StepRecord& at(std::size_t i) const { return steps_[i]; }
  const VarRecord& var_at(std::uint32_t v) const { return vars_[v]; }
  const GeoRecord& geo_at(std::uint32_t g) const { return geos_[g]; }
  std::int64_t int_value(std::uint32_t slot) const { return ints_[slot]; }
  double value_double(const VarRecord& v) const {
    return v.is_int ? static_cast<double>(ints_[v.slot]) : num_double(v.slot);
  }
  std::string value_text(const VarRecord& v) const {
    return v.is_int ? std::to_string(ints_[v.slot]) : num_text(v.slot);
  }
  // Coordinate k of a geometry item, as a double.
  double geo_double(const GeoRecord& g, int k) const {
    return g.kind == GeoKind::pixel ? static_cast<double>(ints_[g.slot + k]) : num_double(g.slot + k);
  }
  std::size_t memory_bytes() const {
    return steps_.capacity() * sizeof(StepRecord) + vars_.capacity() * sizeof(VarRecord) +
           geos_.capacity() * sizeof(GeoRecord) + ints_.capacity() * sizeof(std::int64_t);
  }

 protected:
  std::vector<StepRecord> steps_;
  std::vector<VarRecord> vars_;
  std::vector<GeoRecord> geos_;
  std::vector<std::int64_t> ints_;
};

template <class Num> class Recorder final : public TraceView {
 public:
  static constexpr bool on = true;

  Numeric numeric() const override { return NumericOf<Num>::value; }
  double num_double(std::uint32_t s) const override { return num::to_double(nums_[s]); }
  std::string num_text(std::uint32_t s) const override { return num::to_text(nums_[s]); }
  const Num& num_value(std::uint32_t s) const { return nums_[s]; }

  Recorder& step(std::uint32_t line, StepKind kind) {
    auto nv = static_cast<std::uint32_t>(vars_.size()), ng = static_cast<std::uint32_t>(geos_.size());
    steps_.push_back({line, kind, nv, nv, ng, ng});
    return *this;
  }
  Recorder& num(const char* name, const Num& v) {
    vars_.push_back({name, static_cast<std::uint32_t>(nums_.size()), false});
    nums_.push_back(v);
    steps_.back().var_end++;
    return *this;
  }
  Recorder& idx(const char* name, std::int64_t v) {
    vars_.push_back({name, static_cast<std::uint32_t>(ints_.size()), true});
    ints_.push_back(v);
    steps_.back().var_end++;
    return *this;
  }
  Recorder& pixel(Pixel p) {
    geos_.push_back({GeoKind::pixel, static_cast<std::uint32_t>(ints_.size())});
    ints_.push_back(p.x);
    ints_.push_back(p.y);
    steps_.back().geo_end++;
    return *this;
  }
  // Any number-valued geometry: the values in the order kGeoArity documents.
  template <class... V> Recorder& geo(GeoKind kind, const V&... values) {
    static_assert(sizeof...(V) > 0);
    geos_.push_back({kind, static_cast<std::uint32_t>(nums_.size())});
    (nums_.push_back(values), ...);
    steps_.back().geo_end++;
    return *this;
  }
  Recorder& point(const Vec2<Num>& p) { return geo(GeoKind::point2, p.x, p.y); }
  Recorder& point(const Vec3<Num>& p) { return geo(GeoKind::point3, p.x, p.y, p.z); }

  // Empties the trace but keeps its memory: re-recording (dragging an endpoint) then costs no
  // allocation or page faults.
  void clear() {
    steps_.clear();
    vars_.clear();
    geos_.clear();
    ints_.clear();
    nums_.clear();
  }
  // Room for about `steps` steps of up to 4 variables and 2 geometry items each. Pages that are
  // never written are never faulted in, so a generous reserve is free; regrowth is not.
  void reserve(std::size_t steps) {
    steps_.reserve(steps);
    vars_.reserve(steps * 4);
    nums_.reserve(steps * 4);
    ints_.reserve(steps * 4);
    geos_.reserve(steps * 2);
  }

 private:
  std::vector<Num> nums_;
};

}  // namespace sw
