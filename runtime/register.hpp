// Turns a typed Spec (spec.hpp) into its catalog entry, and registers it: a Spec's file ends with
//   SW_REGISTER(DdaLineSpec);
// and its family is the folder of that file (runtime/lines/ -> "lines"). The entry's open()
// builds an OpenSpec<Spec>: the one place where Spec::parse runs, holding the parsed Input for
// every computation a run handle (run.hpp) asks for.
#pragma once
#include <memory>
#include "bench_harness.hpp"
#include "core/jsonl_probe.hpp"
#include "platform.hpp"
#include "sweep.hpp"

namespace sw {

// A rounded mode that produced NaN or an infinity failed; the result says so, whatever else the
// Spec reports (docs/trace-format.md). Filtered results say whether exact rationals were needed.
template <class Spec> Json result_json(const typename Spec::Output& out, Numeric n, bool fell_back) {
  Json r = Spec::to_json(out);
  if (encode_nonfinite(r) && r.is_object() && !r.contains("failure")) r["failure"] = "nan-or-inf";
  if (n == Numeric::filtered) r["fallback"] = fell_back;
  return r;
}

template <class Spec> class OpenSpec final : public OpenInput {
  using Input = typename Spec::Input;
  using Output = typename Spec::Output;

 public:
  OpenSpec(const Algorithm& alg, const Json& j) : OpenInput(alg, j), in_(Spec::parse(j)) {}
  // A seeded input, parsed already: it has no JSON text (json() is null).
  OpenSpec(const Algorithm& alg, Input in) : OpenInput(alg, Json()), in_(std::move(in)) {}

  void admit(Numeric n) const override {
    if constexpr (names_hook<Spec>(Hook::admit)) Spec::admit(in_, n);
    else (void)n;
  }
  std::optional<std::uint64_t> estimate_steps() const override {
    if constexpr (names_hook<Spec>(Hook::estimate_steps)) return std::uint64_t(Spec::estimate_steps(in_));
    else return std::nullopt;
  }
  Json run(Numeric n) const override {
    bool fb;
    const Output out = compute_mode<Spec>(in_, n, untraced, &fb);
    return result_json<Spec>(out, n, fb);
  }
  void run_to(Numeric n, std::ostream& os) const override {
    bool fb;
    const Output out = compute_mode<Spec>(in_, n, untraced, &fb);
    write_result(out, n, fb, os);
    os << '\n';
  }
  Recorded record(Numeric n) const override {
    Recorded rec;
    bool fb;
    const Output out = compute_mode<Spec>(in_, n, [&](auto t, auto&& compute) {
      auto r = std::make_unique<Recorder<typename decltype(t)::type>>();
      // Reserved memory costs nothing until touched; regrowth copies it all.
      if constexpr (names_hook<Spec>(Hook::estimate_steps)) r->reserve(std::min<std::size_t>(Spec::estimate_steps(in_), std::size_t{1} << 27));
      auto o = compute(*r);
      rec.trace = std::move(r);
      return o;
    }, &fb);
    rec.result = result_json<Spec>(out, n, fb);
    return rec;
  }
  void stream(Numeric n, std::ostream& os) const override {
    if constexpr (kBrowser) {  // no JSONL writer in the page: a quarter of the algorithms' code
      (void)n, (void)os;
      throw InputError("the browser page writes no traces: `stepwise trace` does");
    } else {
      bool fb;
      const Output out = compute_mode<Spec>(in_, n, [&](auto t, auto&& compute) {
        JsonlProbe<typename decltype(t)::type> probe(os);
        auto o = compute(probe);
        probe.finish();
        return o;
      }, &fb);
      os << "{\"result\":";
      write_result(out, n, fb, os);
      os << "}\n";
    }
  }
  Json oracle() const override {
    if constexpr (kBrowser) throw InputError("the browser page has no oracle: `stepwise check` does");
    else return oracle_json(Spec::oracle(in_));
  }
  void oracle_to(std::ostream& os) const override {
    if constexpr (kBrowser) {
      (void)os;
      throw InputError("the browser page has no oracle: `stepwise check` does");
    } else {
      const Output out = Spec::oracle(in_);
      if constexpr (names_hook<Spec>(Hook::write_members)) {
        os << '{';
        Spec::write_members(out, os);
        os << '}';
      } else {
        os << oracle_json(out).dump();
      }
    }
  }

  void sweep(Numeric n, const SweepGrid& g, std::vector<float>& out) const override {
    if constexpr (names_hook<Spec>(Hook::sweeper)) run_sweep<Spec, ImageSweep>(in_, n, g, out);
    else OpenInput::sweep(n, g, out);
  }
  std::optional<std::array<double, 2>> sweep_marker() const override {
    if constexpr (names_hook<Spec>(Hook::sweep_marker)) return Spec::sweep_marker(in_);
    else return std::nullopt;
  }
  Json sweep_sample(const SweepGrid& g, int i, int j) const override {
    if constexpr (names_hook<Spec>(Hook::sweep_input)) return Spec::sweep_input(json(), in_, g, i, j);
    else return OpenInput::sweep_sample(g, i, j);
  }
  void lobe(Numeric n, const SweepGrid& g, std::vector<float>& out) const override {
    if constexpr (names_hook<Spec>(Hook::lobe)) run_sweep<Spec, LobeSweep>(in_, n, g, out);
    else OpenInput::lobe(n, g, out);
  }
  std::optional<std::array<double, 2>> lobe_angles() const override {
    if constexpr (names_hook<Spec>(Hook::lobe)) return Spec::lobe_angles(in_);
    else return std::nullopt;
  }
  Json lobe_sample(const SweepGrid& g, int i) const override {
    if constexpr (names_hook<Spec>(Hook::lobe)) return Spec::lobe_input(json(), in_, g, i);
    else return OpenInput::lobe_sample(g, i);
  }
  std::vector<Polyline2> outline(const Rect2& window, double cell) const override {
    if constexpr (names_hook<Spec>(Hook::outline)) return Spec::outline(in_, window, cell);
    else return OpenInput::outline(window, cell);
  }
  Picture picture(std::int64_t max_side) const override {
    if constexpr (names_hook<Spec>(Hook::picture)) return Spec::picture(in_, max_side);
    else return OpenInput::picture(max_side);
  }
  SummaryTable summary_table(const TraceView& trace) const override {
    if constexpr (names_hook<Spec>(Hook::summary_table)) return Spec::summary_table(in_, trace);
    else return OpenInput::summary_table(trace);
  }

 private:
  static constexpr auto untraced = [](auto, auto&& compute) {
    NoProbe none;
    return compute(none);
  };
  static Json oracle_json(const Output& out) {
    Json r = Spec::to_json(out);
    encode_nonfinite(r);
    return r;
  }
  // The result object, streamed from the output where the Spec writes its members itself.
  static void write_result(const Output& out, Numeric n, bool fb, std::ostream& os) {
    if constexpr (names_hook<Spec>(Hook::write_members)) {
      os << '{';
      Spec::write_members(out, os);
      if (n == Numeric::filtered) os << ",\"fallback\":" << (fb ? "true" : "false");
      os << '}';
    } else {
      os << result_json<Spec>(out, n, fb).dump();
    }
  }

  Input in_;
};

template <class Spec> constexpr bool result_keys_distinct() {
  for (std::size_t i = 0; i < Spec::result_keys.size(); ++i) {
    if (std::string_view(Spec::result_keys[i]).empty()) return false;
    for (std::size_t j = 0; j < i; ++j)
      if (std::string_view(Spec::result_keys[i]) == std::string_view(Spec::result_keys[j])) return false;
  }
  return true;
}

template <class Spec> constexpr bool table_lines_exist() {
  for (std::string_view name : Spec::table_lines)
    if (!Spec::Algo::listing().find(name)) return false;
  return true;
}

// The entry's facts from the Spec (the family is set by the registrar).
template <AlgorithmSpec Spec> Algorithm make_algorithm() {
  static_assert(HookNamedAndDefined<hook_mismatch<Spec>()>::ok);
  Algorithm a;
  a.id = Spec::Algo::id;
  a.summary = Spec::Algo::summary;
  a.listing = Spec::Algo::listing();
  a.views.assign(Spec::views.begin(), Spec::views.end());
  if constexpr (names_hook<Spec>(Hook::handles)) a.handles = Spec::handles();
  a.numerics.assign(Spec::numerics.begin(), Spec::numerics.end());
  a.example = Spec::example;
  if constexpr (names_hook<Spec>(Hook::table_lines)) {
    static_assert(table_lines_exist<Spec>(), "table_lines names a line the listing does not have");
    a.table_lines.assign(Spec::table_lines.begin(), Spec::table_lines.end());
  }
  if constexpr (names_hook<Spec>(Hook::sweeper)) {
    a.sweep.present = true;
    a.sweep.marker = names_hook<Spec>(Hook::sweep_marker);
    a.sweep.sample = names_hook<Spec>(Hook::sweep_input);
    if constexpr (names_hook<Spec>(Hook::sweep_caption)) a.sweep.caption = Spec::sweep_caption;
    if constexpr (names_hook<Spec>(Hook::sweep_shaded)) a.sweep.shaded = Spec::sweep_shaded;
  }
  if constexpr (names_hook<Spec>(Hook::lobe)) a.lobe = {.present = true, .shaded = true, .sample = true, .angles = true, .caption = {}};
  a.outline = names_hook<Spec>(Hook::outline);
  if constexpr (names_hook<Spec>(Hook::result_keys)) {
    static_assert(result_keys_distinct<Spec>(), "result_keys names a key twice, or an empty one");
    a.result_keys.assign(Spec::result_keys.begin(), Spec::result_keys.end());
  }
  static_assert(!names_hook<Spec>(Hook::pick) || names_hook<Spec>(Hook::picture), "a pick needs a picture to click on");
  a.picture.present = names_hook<Spec>(Hook::picture);
  if constexpr (names_hook<Spec>(Hook::pick)) {
    static_assert(!Spec::pick.empty() && Spec::pick[0] == '/', "pick is a JSON pointer into the input (\"/pixel\")");
    a.picture.pick = Spec::pick;
  }
  a.summary_table = names_hook<Spec>(Hook::summary_table);
  if constexpr (names_hook<Spec>(Hook::params)) a.params = Spec::params();
  if constexpr (names_hook<Spec>(Hook::compare_group)) a.compare_group = Spec::compare_group;
  a.fn.open = [](const Algorithm& alg, const Json& j) -> std::shared_ptr<const OpenInput> { return std::make_shared<const OpenSpec<Spec>>(alg, j); };
  if constexpr (names_hook<Spec>(Hook::result_sets)) a.result_sets.assign(Spec::result_sets.begin(), Spec::result_sets.end());
  a.reshapes_result = names_hook<Spec>(Hook::canonical);
  a.fn.canonical = [](Json r) -> Json {
    if constexpr (names_hook<Spec>(Hook::result_sets))
      for (std::string_view key : Spec::result_sets) sort_result_set(r, key);
    if constexpr (names_hook<Spec>(Hook::canonical)) return Spec::canonical(std::move(r));
    else return r;
  };
  a.fn.bench = &bench_spec<Spec>;
  a.fn.bench_sets = [] {
    std::vector<std::string> names;
    for (const auto& set : make_bench_sets<Spec>(BenchSize::quick)) names.push_back(set.name);  // the names of either size
    return names;
  };
  if constexpr (names_hook<Spec>(Hook::contract_inputs)) a.contract_inputs.assign(Spec::contract_inputs.begin(), Spec::contract_inputs.end());
  a.fn.seeded = [](const Algorithm& alg, std::size_t per_set) {
    std::vector<std::shared_ptr<const OpenInput>> opened;
    for (auto& set : make_bench_sets<Spec>(BenchSize::quick))
      for (std::size_t k = 0; k < std::min(per_set, set.inputs.size()); ++k)
        opened.push_back(std::make_shared<const OpenSpec<Spec>>(alg, std::move(set.inputs[k])));
    return opened;
  };
  a.fn.step_cost = [](Numeric n) -> std::size_t {
    if constexpr (names_hook<Spec>(Hook::step_cost)) return Spec::step_cost(n);
    else return (void)n, 1;
  };
  return a;
}

#define SW_REGISTER_CONCAT2(a, b) a##b
#define SW_REGISTER_CONCAT(a, b) SW_REGISTER_CONCAT2(a, b)
// Registers Spec in the catalog, in the family of this file's folder.
#define SW_REGISTER(Spec) \
  static const ::sw::Registrar SW_REGISTER_CONCAT(sw_registrar_, __LINE__)(&::sw::make_algorithm<Spec>, __FILE__)
// Registers the listing of a callee that is no algorithm of its own (a struct with id and listing()).
#define SW_REGISTER_CALLEE(Callee) \
  static const ::sw::CalleeRegistrar SW_REGISTER_CONCAT(sw_callee_, __LINE__)(Callee::id, Callee::listing())

}  // namespace sw
