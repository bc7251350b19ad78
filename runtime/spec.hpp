// The Spec concept: what make_algorithm (register.hpp) needs of an algorithm's Spec. A Spec provides:
//   using Algo = <the listing struct>;
//   static constexpr std::array<View, N> views;              // what the visualizer draws
//   static constexpr std::array<Numeric, N> numerics;
//   static inline const std::string example;                 // default input, JSON text
//   struct Input;  struct Output (with ==);
//   static Input parse(const Json&);                         // validates, throws InputError
//   template <class Num> static auto prepare(const Input&);  // inputs converted to Num
//   template <class Num, class Probe> static Output compute(const Prepared&, Probe&);
//   static Json to_json(const Output&);
//   static std::size_t ops(const Output&);                   // output units, for ns per op
//   static Output oracle(const Input&);                      // independent exact result
//   static std::vector<BenchSet<Input>> bench_sets();        // seeded (or bench_sets(BenchSize))
// Its family is the folder its file registers it in (SW_REGISTER). Besides these, a Spec may
// define optional hooks; it names the ones it defines in
//   static constexpr std::array hooks{Hook::handles, Hook::error, ...};
// and the concept holds the names against the definitions both ways. A misspelt hook, or one with
// the wrong signature, is then a compile error ("names a hook it does not define") instead of a
// hook silently ignored. docs/hooks.md lists every hook and the Specs that define it.
#pragma once
#include <array>
#include <optional>
#include <concepts>
#include <ostream>
#include <string>
#include <vector>
#include "catalog.hpp"

namespace sw {

enum class Hook : std::uint8_t {
  filters,         // using Filters = std::tuple<stages...>
  handles,         // static std::vector<Handle> handles()
  estimate_steps,  // static std::size_t estimate_steps(const Input&)
  step_cost,       // static std::size_t step_cost(Numeric): work-budget units one step costs in that mode
  write_members,   // static void write_members(const Output&, std::ostream&)
  canonical,       // static Json canonical(const Json& result)
  error,           // static double error(const Output& got, const Output& exact), with static constexpr std::string_view error_unit
  bench_runs,      // static bool bench_runs(const std::string& set, Numeric)
  table_lines,     // static constexpr std::array table_lines{"name"sv, ...}
  sweeper,         // template <class Num> static auto sweeper(const Input&, const SweepGrid&), with sweep_value
  sweep_marker,    // static std::optional<std::array<double, 2>> sweep_marker(const Input&)
  sweep_caption,   // static constexpr std::string_view sweep_caption
  sweep_input,     // static Json sweep_input(Json, const Input&, const SweepGrid&, int, int)
  outline,         // static std::vector<Polyline2> outline(const Input&, const Rect2&, double cell)
  sweep_shaded,    // static constexpr bool sweep_shaded = true: the sweep's values are intensities in [0, 1]
  lobe,            // template <class Num> static auto lobe_sweeper(const Input&, const SweepGrid&), with sweep_value,
                   // lobe_angles(const Input&) and lobe_input(Json, const Input&, const SweepGrid&, int)
  params,          // static std::vector<Param> params()
  compare_group,   // static constexpr std::string_view compare_group
  admit,           // static void admit(const Input&, Numeric): throws InputError if the input cannot run in that mode
  result_keys,     // static constexpr std::array result_keys{"hit"sv, ...}: keys every result has, which views may read
  picture,         // static Picture picture(const Input&, std::int64_t max_side): a picture of the input (the scene view)
  pick,            // static constexpr std::string_view pick = "/pixel": the input's pointer a click on the picture sets
  summary_table,   // static SummaryTable summary_table(const Input&, const TraceView&): a table from a recorded trace
  contract_inputs, // static constexpr std::array contract_inputs{R"({...})"sv, ...}: inputs (JSON) that reach listing lines
                   // the example and the seeded sets miss (a degenerate case), traced by `list --contract`
  result_sets,     // static constexpr std::array result_sets{"pixels"sv, ...}: result members the oracle states as sets,
                   // which the canonical form sorts
};
inline constexpr std::size_t kHookCount = 25;

template <class S> constexpr bool names_hook(Hook h) {
  if constexpr (requires { S::hooks; })
    for (Hook x : S::hooks)
      if (x == h) return true;
  return false;
}

template <class S> constexpr bool defines_hook(Hook h) {
  using In = typename S::Input;
  using Out = typename S::Output;
  switch (h) {
    case Hook::filters: return requires { typename S::Filters; };
    case Hook::handles: return requires { { S::handles() } -> std::same_as<std::vector<Handle>>; };
    case Hook::estimate_steps: return requires(const In& in) { { S::estimate_steps(in) } -> std::convertible_to<std::size_t>; };
    case Hook::step_cost: return requires(Numeric n) { { S::step_cost(n) } -> std::convertible_to<std::size_t>; };
    case Hook::write_members: return requires(const Out& o, std::ostream& os) { S::write_members(o, os); };
    case Hook::canonical: return requires(const Json& r) { { S::canonical(r) } -> std::convertible_to<Json>; };
    case Hook::error: return requires(const Out& o) { { S::error(o, o) } -> std::convertible_to<double>; { S::error_unit } -> std::convertible_to<std::string_view>; };
    case Hook::bench_runs: return requires(const std::string& set, Numeric n) { { S::bench_runs(set, n) } -> std::convertible_to<bool>; };
    case Hook::table_lines: return requires { S::table_lines; };
    case Hook::sweeper:
      return requires(const In& in, const SweepGrid& g, const Out& o) {
        S::template sweeper<Rational>(in, g);
        { S::sweep_value(o) } -> std::convertible_to<float>;
      };
    case Hook::sweep_marker: return requires(const In& in) { S::sweep_marker(in); };
    case Hook::sweep_caption: return requires { { S::sweep_caption } -> std::convertible_to<std::string_view>; };
    case Hook::sweep_input: return requires(const In& in, const SweepGrid& g) { { S::sweep_input(Json(), in, g, 0, 0) } -> std::convertible_to<Json>; };
    case Hook::outline: return requires(const In& in, const Rect2& r) { S::outline(in, r, 1.0); };
    case Hook::sweep_shaded: return requires { { S::sweep_shaded } -> std::convertible_to<bool>; };
    case Hook::lobe:
      return requires(const In& in, const SweepGrid& g, const Out& o) {
        S::template lobe_sweeper<Rational>(in, g);
        { S::sweep_value(o) } -> std::convertible_to<float>;
        { S::lobe_angles(in) } -> std::convertible_to<std::optional<std::array<double, 2>>>;
        { S::lobe_input(Json(), in, g, 0) } -> std::convertible_to<Json>;
      };
    case Hook::params: return requires { { S::params() } -> std::same_as<std::vector<Param>>; };
    case Hook::compare_group: return requires { { S::compare_group } -> std::convertible_to<std::string_view>; };
    case Hook::admit: return requires(const In& in, Numeric n) { S::admit(in, n); };
    case Hook::result_keys:
      return requires { { S::result_keys[0] } -> std::convertible_to<std::string_view>; S::result_keys.size(); };
    case Hook::picture: return requires(const In& in) { { S::picture(in, std::int64_t{1}) } -> std::same_as<Picture>; };
    case Hook::pick: return requires { { S::pick } -> std::convertible_to<std::string_view>; };
    case Hook::summary_table: return requires(const In& in, const TraceView& t) { { S::summary_table(in, t) } -> std::same_as<SummaryTable>; };
    case Hook::contract_inputs:
      return requires { { S::contract_inputs[0] } -> std::convertible_to<std::string_view>; S::contract_inputs.size(); };
    case Hook::result_sets:
      return requires { { S::result_sets[0] } -> std::convertible_to<std::string_view>; S::result_sets.size(); };
  }
  return false;
}

// The first hook named but not defined, or defined but not named; kHookCount if none.
template <class S> constexpr std::size_t hook_mismatch() {
  for (std::size_t k = 0; k < kHookCount; ++k)
    if (names_hook<S>(Hook(k)) != defines_hook<S>(Hook(k))) return k;
  return kHookCount;
}

// What a bench asks of a Spec's set generator: quick (the default) or full (`bench --full`, the
// sets as documented). The harness cuts every set to BenchOptions::max_cases itself; a generator
// whose single cases are long takes this as `bench_sets(BenchSize)` and shortens them when quick
// (the lines' long set: 4 lines of 4 million pixels each, 65 thousand when quick).
enum class BenchSize : std::uint8_t { quick, full };

template <class S> auto make_bench_sets(BenchSize size) {
  if constexpr (requires { S::bench_sets(size); }) return S::bench_sets(size);
  else return (void)size, S::bench_sets();
}

template <class S>
concept AlgorithmSpec = requires {
  typename S::Algo;
  typename S::Input;
  typename S::Output;
  { S::Algo::id } -> std::convertible_to<std::string_view>;
  { S::Algo::listing() } -> std::same_as<Listing>;
  S::views.size();
  S::numerics.size();
  { S::example } -> std::convertible_to<std::string>;
} && (requires { S::bench_sets(); } || requires { S::bench_sets(BenchSize::full); }) && requires(const Json& j, const typename S::Input& in, const typename S::Output& o) {
  { S::parse(j) } -> std::same_as<typename S::Input>;
  { S::to_json(o) } -> std::convertible_to<Json>;
  { S::ops(o) } -> std::convertible_to<std::size_t>;
  { S::oracle(in) } -> std::same_as<typename S::Output>;
  { o == o } -> std::convertible_to<bool>;
};

// Instantiated by make_algorithm: a mismatch fails here, and the compiler's message shows K, the
// Hook that is named but not defined (or misspelt), or defined but not named.
template <std::size_t K> struct HookNamedAndDefined {
  static_assert(K == kHookCount, "a Spec's `hooks` and its definitions disagree at Hook(K) (runtime/spec.hpp)");
  static constexpr bool ok = true;
};

}  // namespace sw
