// Shared by the lighting models' tests: the nine entries by id, running one on a parsed input in
// any number type (directly, so a Recorder<Rational> can be inspected), the oracle's value, a
// closeness test in rationals, and seeded random inputs (small exact rationals).
#pragma once
#include <catch2/catch.hpp>
#include <array>
#include <fstream>
#include <random>
#include <string>
#include <vector>
#include "lighting/lighting_input.hpp"
#include "lighting/models.hpp"
#include "lighting_oracle.hpp"

namespace sw::testing::lighting_models {

using lighting_io::ModelInput;
using Q = Rational;

inline constexpr std::array<const char*, 9> kIds = {"lambert", "minnaert", "oren-nayar", "toon", "phong",
                                                   "blinn-phong", "gaussian", "beckmann", "cook-torrance"};

inline lighting::ModelParams<double> params_double(const lighting::ModelParams<Q>& q) {
  lighting::ModelParams<double> p;
  p.minnaert_k = q.minnaert_k.get_d(), p.sigma = q.sigma.get_d(), p.shininess = q.shininess.get_d(), p.m = q.m.get_d(), p.ior = q.ior.get_d();
  if (q.toon) p.toon = q.toon->get_d();
  p.toon_above = q.toon_above, p.fresnel = q.fresnel, p.shadowing = q.shadowing;
  return p;
}
template <class Num> lighting::ModelParams<Num> params_as(const lighting::ModelParams<Q>& q) {
  if constexpr (std::is_same_v<Num, Q>) return q;
  else if constexpr (std::is_same_v<Num, double>) return params_double(q);
  else {
    const auto d = params_double(q);
    lighting::ModelParams<float> p;
    p.minnaert_k = float(d.minnaert_k), p.sigma = float(d.sigma), p.shininess = float(d.shininess), p.m = float(d.m), p.ior = float(d.ior);
    if (d.toon) p.toon = float(*d.toon);
    p.toon_above = d.toon_above, p.fresnel = d.fresnel, p.shadowing = d.shadowing;
    return p;
  }
}

// f(type_identity<Algo>) for the entry `id`.
template <class F> auto with_algo(std::string_view id, F&& f) {
  using namespace sw::lighting;
  if (id == "lambert") return f(std::type_identity<Lambert>{});
  if (id == "minnaert") return f(std::type_identity<Minnaert>{});
  if (id == "oren-nayar") return f(std::type_identity<OrenNayar>{});
  if (id == "toon") return f(std::type_identity<Toon>{});
  if (id == "phong") return f(std::type_identity<Phong>{});
  if (id == "blinn-phong") return f(std::type_identity<BlinnPhong>{});
  if (id == "gaussian") return f(std::type_identity<Gaussian>{});
  if (id == "beckmann") return f(std::type_identity<Beckmann>{});
  return f(std::type_identity<CookTorrance>{});
}

// The entry's term on `in` in number type Num, with the decisions made on the exact input.
template <class Num, class Probe> Num run_model(std::string_view id, const ModelInput& in, Probe& probe) {
  return with_algo(id, [&]<class A>(std::type_identity<A>) -> Num {
    return lighting::evaluate<A>(in.choice, to_num<Num>(in.n), to_num<Num>(in.l), to_num<Num>(in.e), params_as<Num>(in.p), probe, in.signs);
  });
}
template <class Num> Num run_model(std::string_view id, const ModelInput& in) {
  NoProbe none;
  return run_model<Num>(id, in, none);
}

inline lighting_oracle::OracleTerm oracle_of(std::string_view, const ModelInput& in) {
  return lighting_oracle::term(in.choice, in.n, in.l, in.e, in.p);
}

// |got - want| <= 2^-rel |want| + 2^-abs.
inline bool close(const Q& got, const Q& want, int rel = 200, int abs_bits = 250) {
  Q r(1), a(1);
  r >>= rel, a >>= abs_bits;
  return abs(Q(got - want)) <= r * abs(want) + a;
}

// Seeded inputs of small exact rationals: vectors with components in [-4, 4] in steps of 1/4
// (zero components often), the light and the eye mostly above the surface, and the model's
// parameters from a few exact values.
struct Gen {
  std::mt19937_64 rng;
  explicit Gen(std::uint64_t seed) : rng(seed) {}
  int pick(int lo, int hi) { return lo + int(rng() % std::uint64_t(hi - lo + 1)); }
  Q coord() { return rng() % 4 == 0 ? Q(0) : Q(Q(pick(-16, 16)) / 4); }
  Vec3<Q> vec() {
    for (;;) {
      const Vec3<Q> v{coord(), coord(), coord()};
      if (!(v == Vec3<Q>{})) return v;
    }
  }
  static Json js(const Vec3<Q>& v) { return Json::array({v.x.get_str(), v.y.get_str(), v.z.get_str()}); }
  Json params(std::string_view id) {
    Json j = Json::object();
    auto frac = [&](std::initializer_list<const char*> xs) { return Json(*(xs.begin() + rng() % xs.size())); };
    if (id == "minnaert") j["k"] = frac({"0", "1/4", "1/2", "3/4", "1"});
    if (id == "oren-nayar") j["sigma"] = frac({"0", "1/4", "1/2", "1"});
    if (id == "toon") {
      const int d = pick(0, 2);
      j["diffuse"] = std::array{"lambert", "minnaert", "oren-nayar"}[d];
      if (d == 1) j["k"] = frac({"1/4", "1/2", "1"});
      if (d == 2) j["sigma"] = frac({"0", "1/2", "1"});
      j["cutoff"] = frac({"0", "1/4", "1/2", "3/5", "1"});
    }
    if (id == "phong" || id == "blinn-phong") j["shininess"] = frac({"0", "1", "5/2", "20", "100"});
    if (id == "gaussian" || id == "beckmann" || id == "cook-torrance") j["m"] = frac({"1/10", "3/10", "1/2", "1"});
    if (id == "cook-torrance") j["ior"] = frac({"1", "3/2", "5"}), j["fresnel"] = frac({"exact", "schlick", "one"});
    if (id == "cook-torrance" && rng() % 5 == 0) j["shadowing"] = false;
    return j;
  }
  // n, then l and e flipped into n's half-space three times in four (so most frames are lit).
  Json input(std::string_view id) {
    Json j = params(id);
    const Vec3<Q> n = vec();
    auto toward = [&](Vec3<Q> v) {
      if (sgn(dot(v, n)) < 0 && rng() % 4 != 0) v = Q(-1) * v;
      return v;
    };
    j["n"] = js(n), j["l"] = js(toward(vec())), j["e"] = js(toward(vec()));
    return j;
  }
};

// The hard-case corpus, tests/cases/lighting/models.jsonl: {"name", "algorithm", "note", "input"}.
struct CorpusCase {
  std::string name, algorithm;
  Json input;
};
inline std::vector<CorpusCase> corpus() {
  std::ifstream f(std::string(SW_SOURCE_DIR) + "/tests/cases/lighting/models.jsonl");
  std::vector<CorpusCase> out;
  std::string line;
  while (std::getline(f, line))
    if (!line.empty() && line[0] == '{') {
      const Json j = Json::parse(line);
      if (j.contains("algorithm")) out.push_back({j.at("name"), j.at("algorithm"), j.at("input")});
    }
  return out;
}

}  // namespace sw::testing::lighting_models
