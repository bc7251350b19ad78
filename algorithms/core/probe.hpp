// Probes: where an algorithm's steps go.
//  - NoProbe: nothing. Algorithms guard every step with `if constexpr (Probe::on)`, so no argument
//    is evaluated and the untraced code is the plain loop.
//  - Recorder<Num>: in memory, random access (the app steps backward by indexing).
//  - JsonlProbe<Num> (jsonl_probe.hpp): streams JSON lines; memory stays flat.
#pragma once
#include <concepts>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>
#include "core/column.hpp"
#include "core/emitters.hpp"
#include "core/number.hpp"
#include "core/step.hpp"
#include "core/vec.hpp"

namespace sw {

struct NoProbe {
  static constexpr bool on = false;
};

// What an algorithm asks of its number type: small integer constants, the ring operations and an
// order. float, double, int64, Rational, Interval and Mag model it.
template <class N>
concept NumberType = std::copyable<N> && std::constructible_from<N, int> && requires(const N a, const N b) {
  {N(a + b)};
  {N(a - b)};
  {N(a * b)};
  { a < b } -> std::convertible_to<bool>;
};

// Where steps go: NoProbe (off: no step is evaluated) or a probe with step(line, kind) whose
// result takes the recording calls (Recorder, JsonlProbe).
template <class P>
concept StepProbe = requires {
  { P::on } -> std::convertible_to<bool>;
}
&&(!P::on || requires(P & p) { p.step(std::uint32_t{1}, StepKind::init); });

// A nested listing for the lifetime of a scope: `const auto call = nested<Refract>(probe);` enters
// Refract's listing (probe.enter(id, listing)) and leaves it when `call` goes out of scope, so that
// every way out of the scope (a return, an exception) leaves exactly once. The steps between are
// the callee's. For a probe that is off, nested() returns an empty object: nothing is evaluated.
template <class Probe> class [[nodiscard]] NestedScope {
 public:
  NestedScope(Probe& probe, std::string_view id, const Listing& listing) : probe_(probe) { probe_.enter(id, listing); }
  NestedScope(const NestedScope&) = delete;
  NestedScope& operator=(const NestedScope&) = delete;
  ~NestedScope() { probe_.leave(); }

 private:
  Probe& probe_;
};
struct [[maybe_unused]] NoNestedScope {};

template <class Algo, class Probe> [[nodiscard]] auto nested(Probe& probe) {
  if constexpr (Probe::on) return NestedScope<Probe>(probe, Algo::id, Algo::listing());
  else return NoNestedScope{};
}

// Steps as stored: ranges into the shared variable and geometry arrays.
struct StepRecord {
  std::uint32_t line;  // in the listing of `scope`
  StepKind kind;
  std::uint8_t scope;  // 0: the algorithm's own listing; k: the callee scope_listing(k)
  std::uint32_t var_begin, var_end, geo_begin, geo_end;
};
// A variable is a scalar, a vector of 2 or 3 numbers, a colour (r, g, b in [0, 1] by convention)
// or a short list (an edge-table row, a traversal stack) of numbers or integers.
enum class VarShape : std::uint8_t { scalar, vector, colour, list };
struct VarRecord {
  const char* name;    // a string literal from the algorithm
  std::uint32_t slot;  // into the number or the integer store
  bool is_int;
  std::uint8_t count;  // how many values from slot: 1 for a scalar, 2 or 3 for a vector, 3 for a colour
  VarShape shape = VarShape::scalar;
};
struct GeoRecord {
  GeoKind kind;
  Life life = Life::step;
  std::uint16_t count;             // geo_arity(kind), or the list's length for variable kinds (< 2^16)
  std::uint32_t slot;              // first of `count` values (integers for integer kinds)
  const char* label = nullptr;     // a string literal from the algorithm, or none
  std::uint32_t value = kNoValue;  // the number store's slot of the item's value (a colour key), or none
  static constexpr std::uint32_t kNoValue = 0xffffffffu;
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
  // The callee listings entered during the run (nested scopes), by scope number from 1; the
  // algorithm's own listing is scope 0 and not stored here.
  const Listing& scope_listing(std::uint8_t k) const { return scopes_[k - 1].listing; }
  std::string_view scope_id(std::uint8_t k) const { return scopes_[k - 1].id; }
  const StepRecord& at(std::size_t i) const { return steps_[i]; }
  const VarRecord& var_at(std::uint32_t v) const { return vars_[v]; }
  const GeoRecord& geo_at(std::uint32_t g) const { return geos_[g]; }
  std::int64_t int_value(std::uint32_t slot) const { return ints_[slot]; }
  // Component k of a variable as a double (a scalar is component 0).
  double component_double(const VarRecord& v, std::uint32_t k) const {
    return v.is_int ? static_cast<double>(ints_[v.slot + k]) : num_double(v.slot + k);
  }
  // A scalar's value (a vector's first component; 0 for an empty list).
  double value_double(const VarRecord& v) const { return v.count ? component_double(v, 0) : 0; }
  // The lossless text: "(x, y, z)" for vectors, "rgb(r, g, b)" for colours, "[a, b]" for lists.
  std::string value_text(const VarRecord& v) const {
    auto part = [&](std::uint32_t k) { return v.is_int ? std::to_string(ints_[v.slot + k]) : num_text(v.slot + k); };
    if (v.shape == VarShape::scalar) return part(0);
    std::string t = v.shape == VarShape::colour ? "rgb(" : v.shape == VarShape::list ? "[" : "(";
    for (std::uint32_t k = 0; k < v.count; ++k) t += (k ? ", " : "") + part(k);
    return t + (v.shape == VarShape::list ? "]" : ")");
  }
  // Coordinate k of a geometry item, as a double.
  double geo_double(const GeoRecord& g, int k) const {
    return geo_desc(g.kind).integer ? static_cast<double>(ints_[g.slot + k]) : num_double(g.slot + k);
  }
  std::optional<double> geo_value(const GeoRecord& g) const {
    return g.value == GeoRecord::kNoValue ? std::nullopt : std::optional(num_double(g.value));
  }

 protected:
  Column<StepRecord> steps_;
  Column<VarRecord> vars_;
  Column<GeoRecord> geos_;
  Column<std::int64_t> ints_;
  struct Scope {
    std::string_view id;
    Listing listing;
  };
  std::vector<Scope> scopes_;
};

// Check: void, or a type whose static check(std::span<const Num>) is handed each step's numbers
// as the next step starts; the steps are then forgotten (the scopes entered stay), so a run of
// any length is checked in constant memory (filtered mode's certification, modes.hpp). A plain
// recorder pays nothing for it.
template <class Num, class Check = void>
class Recorder final : public TraceView, public GeometryEmitters<Recorder<Num, Check>, Num> {
 public:
  static constexpr bool on = true;

  Numeric numeric() const override { return NumericOf<Num>::value; }
  double num_double(std::uint32_t s) const override { return num::to_double(nums_[s]); }
  std::string num_text(std::uint32_t s) const override { return num::to_text(nums_[s]); }
  const Num& num_value(std::uint32_t s) const { return nums_[s]; }
  std::span<const Num> numbers() const { return nums_; }  // every number recorded, variables and geometry

  // The stores are Columns (column.hpp), whose push_back always inlines: with std::vector, GCC
  // called push_back out of line for every item, a third of the cost of a step.
  Recorder& step(std::uint32_t line, StepKind kind) {
    if constexpr (!std::is_void_v<Check>) roll();
    if (depth_ > max_depth_) [[unlikely]]
      return discarded(line, kind);
    auto nv = static_cast<std::uint32_t>(vars_.size()), ng = static_cast<std::uint32_t>(geos_.size());
    steps_.push_back({line, kind, scope_, nv, nv, ng, ng});
    return *this;
  }
  // Nested listings: the steps between enter and leave are the callee's, on its listing. Calls
  // nest; a callee deeper than max_depth is summarised (its steps are not recorded; the caller's
  // own step shows its outcome).
  void enter(std::string_view id, const Listing& listing) {
    ++depth_;
    if (depth_ > max_depth_) return;
    std::size_t k = 0;
    while (k < scopes_.size() && scopes_[k].id != id) ++k;
    if (k == scopes_.size()) {
      if (k == 255) throw std::length_error("more than 255 different nested listings in one trace");
      scopes_.push_back({id, listing});
    }
    stack_.push_back(static_cast<std::uint8_t>(k + 1));
    scope_ = stack_.back();
  }
  void leave() {
    if (depth_-- > max_depth_) return;
    stack_.pop_back();
    scope_ = stack_.empty() ? 0 : stack_.back();
  }
  void set_max_depth(int d) { max_depth_ = d; }
  Recorder& num(const char* name, const Num& v) {
    vars_.push_back({name, static_cast<std::uint32_t>(nums_.size()), false, 1});
    nums_.push_back(v);
    steps_.back().var_end++;
    return *this;
  }
  Recorder& idx(const char* name, std::int64_t v) {
    vars_.push_back({name, static_cast<std::uint32_t>(ints_.size()), true, 1});
    ints_.push_back(v);
    steps_.back().var_end++;
    return *this;
  }
  // A vector variable: its components under one name.
  Recorder& vec(const char* name, const Vec2<Num>& v) { return components(name, {v.x, v.y}); }
  Recorder& vec(const char* name, const Vec3<Num>& v) { return components(name, {v.x, v.y, v.z}); }
  Recorder& colour(const char* name, const Vec3<Num>& rgb) {
    components(name, {rgb.x, rgb.y, rgb.z});
    vars_.back().shape = VarShape::colour;
    return *this;
  }
  // A short list (at most kMaxListLength entries) of numbers, or of integers.
  Recorder& list(const char* name, std::span<const Num> xs) {
    check_list(xs.size());
    vars_.push_back(
        {name, static_cast<std::uint32_t>(nums_.size()), false, static_cast<std::uint8_t>(xs.size()), VarShape::list});
    for (const Num& x : xs) nums_.push_back(x);
    steps_.back().var_end++;
    return *this;
  }
  Recorder& ilist(const char* name, std::span<const std::int64_t> xs) {
    check_list(xs.size());
    vars_.push_back({name, static_cast<std::uint32_t>(ints_.size()), true, static_cast<std::uint8_t>(xs.size()), VarShape::list});
    for (std::int64_t x : xs) ints_.push_back(x);
    steps_.back().var_end++;
    return *this;
  }
  Recorder& pixel(Pixel p) { return igeo(GeoKind::pixel, p.x, p.y); }
  // A run of pixels on row j from column i0 to i1 (both included).
  Recorder& span(std::int64_t j, std::int64_t i0, std::int64_t i1) { return igeo(GeoKind::span, j, i0, i1); }
  // Any number-valued geometry: the values in the order SW_GEO_KINDS documents.
  template <class... V> Recorder& geo(GeoKind kind, const V&... values) {
    static_assert(sizeof...(V) > 0);
    geos_.push_back({kind, Life::step, sizeof...(V), static_cast<std::uint32_t>(nums_.size())});
    (nums_.push_back(values), ...);
    steps_.back().geo_end++;
    return *this;
  }
  // A variable-length kind (polyline, polygon): the points' coordinates in order.
  Recorder& geo_list(GeoKind kind, std::span<const Vec2<Num>> points) {
    if (points.size() > 32767) throw std::length_error("a geometry list of more than 32767 points");
    geos_.push_back({kind, Life::step, static_cast<std::uint16_t>(2 * points.size()), static_cast<std::uint32_t>(nums_.size())});
    for (const auto& p : points) nums_.push_back(p.x), nums_.push_back(p.y);
    steps_.back().geo_end++;
    return *this;
  }

  Recorder& components(const char* name, std::initializer_list<Num> xs) {
    vars_.push_back(
        {name, static_cast<std::uint32_t>(nums_.size()), false, static_cast<std::uint8_t>(xs.size()), VarShape::vector});
    for (const Num& x : xs) nums_.push_back(x);
    steps_.back().var_end++;
    return *this;
  }
  // An integer-valued geometry item (pixel, span).
  template <class... I> Recorder& igeo(GeoKind kind, I... values) {
    geos_.push_back({kind, Life::step, sizeof...(I), static_cast<std::uint32_t>(ints_.size())});
    (ints_.push_back(static_cast<std::int64_t>(values)), ...);
    steps_.back().geo_end++;
    return *this;
  }

  // Modifiers of the geometry item just emitted: its label (a string literal), its lifetime, and
  // a value a view colours it by (an edge function's sign, a distance).
  Recorder& label(const char* text) {
    geos_.back().label = text;
    return *this;
  }
  Recorder& keep() { return life(Life::keep); }
  Recorder& replace() { return life(Life::replace); }
  Recorder& life(Life l) {
    geos_.back().life = l;
    return *this;
  }
  Recorder& value(const Num& v) {
    geos_.back().value = static_cast<std::uint32_t>(nums_.size());
    nums_.push_back(v);
    return *this;
  }

  // Empties the trace but keeps its memory: re-recording (dragging an endpoint) then costs no
  // allocation or page faults.
  void clear() {
    steps_.clear();
    vars_.clear();
    geos_.clear();
    ints_.clear();
    nums_.clear();
    scopes_.clear();
    stack_.clear();
    depth_ = 0;
    scope_ = 0;
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
  RecordStore<Num> nums_;
  static void check_list(std::size_t n) {
    if (n > kMaxListLength) throw std::length_error("a list variable of more than 64 entries");
  }
  // A summarised callee's steps go to a scratch recorder, emptied at each step, so that the
  // recording calls need no check of their own.
  [[gnu::cold, gnu::noinline]] Recorder& discarded(std::uint32_t line, StepKind kind) {
    if (!scratch_) scratch_ = std::make_unique<Recorder>();
    scratch_->clear();
    scratch_->steps_.push_back({line, kind, 0, 0, 0, 0, 0});
    return *scratch_;
  }

  // A checking recorder: the steps so far are checked and forgotten. After the run, numbers()
  // holds the last step's.
  void roll() {
    Check::check(nums_);
    steps_.clear(), vars_.clear(), geos_.clear(), ints_.clear(), nums_.clear();
  }

  std::vector<std::uint8_t> stack_;  // the scopes entered and not left
  int depth_ = 0, max_depth_ = 8;
  std::uint8_t scope_ = 0;  // the innermost recorded scope
  std::unique_ptr<Recorder> scratch_;
};

}  // namespace sw
