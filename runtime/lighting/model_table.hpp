// The reflection models as one table: a row per model entry (id, the term it runs, its parameters,
// its example) and a row per numeric parameter (input key, accepted range, slider, random ranges).
// Input parsing, the Specs (examples, sliders, bench sets) and toon's inner model read it; the
// oracle dispatches on the row's ModelChoice and keeps its own formulas. A new model costs its
// formula (algorithms/lighting/), its row here, its oracle formula and its tests.
#pragma once
#include <random>
#include <string_view>
#include <vector>
#include "bench_harness.hpp"
#include "catalog.hpp"
#include "input.hpp"
#include "lighting/brdf.hpp"

namespace sw::lighting_io {

// One numeric parameter: the input key, the range an input may take ([lo, hi], lo excluded when
// lo_open), the slider (range, scale, text), the bench sets' generators (uniform in [rand_lo,
// rand_hi], rounded to float; the "hard" set picks from `hard`, or is uniform when it is empty), and
// where it lives in ModelParams (set, get).
struct ModelParam {
  std::string_view key;
  double lo, hi;
  bool lo_open;
  double slider_lo, slider_hi;
  bool logarithmic;
  std::string_view help;
  double rand_lo, rand_hi;
  std::vector<double> hard;
  void (*set)(lighting::ModelParams<Rational>&, const Rational&);
  Rational (*get)(const lighting::ModelParams<Rational>&);
};

// One model entry. `toon`: the entry also takes "diffuse" (a diffuse row's id, with that row's
// parameters). `fresnel`: it also takes "fresnel" (exact, schlick, one) and an optional boolean
// "shadowing". `bounded`: its exact term lies in [0, 1], so a rounded value above 1 is a failure.
struct ModelRow {
  std::string_view id;
  lighting::ModelChoice choice;
  std::vector<const ModelParam*> params;
  bool toon = false, fresnel = false, bounded = false;
  std::string_view example;
};

const std::vector<ModelRow>& model_table();
const ModelRow& model_row(std::string_view id);  // InputError for an unknown id
// A diffuse model by name (toon's "diffuse"): lambert, minnaert, oren-nayar.
const ModelRow& diffuse_row(const Json& name, const std::string& what);
// Every parameter's slider, pointing at its input key (each shows when the input has the key).
std::vector<Param> model_sliders();
// Random parameters for a row's entry: the bench sets' generator.
Json random_params(const ModelRow& row, std::mt19937_64& rng, bool hard);
struct ModelInput;
// The bench sets of the entry `id`: "random" frames and "hard" ones (grazing, l = e, huge exponents, tiny and huge lengths).
std::vector<BenchSet<ModelInput>> model_bench_sets(std::string_view id);

}  // namespace sw::lighting_io
