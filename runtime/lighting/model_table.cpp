#include "lighting/model_table.hpp"
#include <algorithm>
#include <cmath>
#include "lighting/lighting_input.hpp"

namespace sw::lighting_io {

// The rows themselves (model_table()) are defined in model_specs.cpp, beside the Specs they register.
const ModelRow& model_row(std::string_view id) {
  for (const ModelRow& r : model_table())
    if (r.id == id) return r;
  throw InputError("input: unknown reflection model '" + std::string(id) + "'");
}

const ModelRow& diffuse_row(const Json& name, const std::string& what) {
  std::string known;
  for (const ModelRow& r : model_table()) {
    if (r.choice.specular || r.toon) continue;
    if (name.is_string() && name.get<std::string>() == r.id) return r;
    known += (known.empty() ? "" : ", ") + std::string(r.id);
  }
  if (!name.is_string()) throw InputError(what + ": expected a diffuse model's name (" + known + ")");
  throw InputError(what + ": unknown diffuse model '" + name.get<std::string>() + "' (" + known + ")");
}

std::vector<Param> model_sliders() {
  std::vector<Param> out;
  for (const ModelRow& r : model_table())
    for (const ModelParam* p : r.params)
      if (std::none_of(out.begin(), out.end(), [&](const Param& q) { return q.label == p->key; }))
        out.push_back({"/" + std::string(p->key), std::string(p->key), p->slider_lo, p->slider_hi, p->logarithmic, std::string(p->help)});
  return out;
}

Json random_params(const ModelRow& row, std::mt19937_64& rng, bool hard) {
  auto u = [&](double lo, double hi) { return double(float(std::uniform_real_distribution<double>(lo, hi)(rng))); };
  auto draw = [&](const ModelParam& p, bool h) { return h && !p.hard.empty() ? p.hard[rng() % p.hard.size()] : u(p.rand_lo, p.rand_hi); };
  Json j = Json::object();
  if (row.toon) {  // the inner diffuse model first, its parameters uniform
    std::vector<const ModelRow*> inner;
    for (const ModelRow& r : model_table())
      if (!r.choice.specular && !r.toon) inner.push_back(&r);
    const ModelRow& d = *inner[rng() % inner.size()];
    j["diffuse"] = d.id;
    for (const ModelParam* p : d.params) j[std::string(p->key)] = draw(*p, false);
  }
  for (const ModelParam* p : row.params) j[std::string(p->key)] = draw(*p, hard);
  if (row.fresnel) j["fresnel"] = rng() % 2 ? "exact" : "schlick";
  return j;
}

// Seeded sets: "random" frames (directions uniform on the sphere, lengths from 1/8 to 8, the light
// and the eye in the normal's hemisphere nine times in ten; parameters uniform in their ranges),
// and "hard": grazing light and eye (n.l, n.e = 0, 1e-3 ... 1e-12), l = e, l = -e, huge
// exponents (10^4), sigma = 1, k = 0, lengths from 1e-30 to 1e14, denormal components. Coordinates are
// floats, so float mode reads the input exactly (except the denormal cases, beyond float).
std::vector<BenchSet<ModelInput>> model_bench_sets(std::string_view id) {
  const ModelRow& row = model_row(id);
  std::mt19937_64 rng(4242 + id.size());
  std::normal_distribution<double> gauss;
  auto u = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  auto fl = [](double x) { return double(float(x)); };
  auto dir = [&](double len) {
    Vec3<double> v{gauss(rng), gauss(rng), gauss(rng)};
    const double s = len / std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return Vec3<double>{fl(s * v.x), fl(s * v.y), fl(s * v.z)};
  };
  auto js = [](const Vec3<double>& v) { return Json::array({v.x, v.y, v.z}); };
  auto make = [&](Json j, const Vec3<double>& n, const Vec3<double>& l, const Vec3<double>& e) {
    j["n"] = js(n), j["l"] = js(l), j["e"] = js(e);
    return parse_model_input(id, j);
  };
  auto flip_into = [](Vec3<double> v, const Vec3<double>& n, bool into) {
    const double d = v.x * n.x + v.y * n.y + v.z * n.z;
    if ((d < 0) == into) v = Vec3<double>{-v.x, -v.y, -v.z};
    return v;
  };
  BenchSet<ModelInput> random{"random", {}}, hard{"hard", {}};
  for (int k = 0; k < 2000; ++k) {
    const Vec3<double> n = dir(std::exp2(u(-3, 3)));
    const Vec3<double> l = flip_into(dir(std::exp2(u(-3, 3))), n, rng() % 10 != 0), e = flip_into(dir(std::exp2(u(-3, 3))), n, rng() % 10 != 0);
    random.inputs.push_back(make(random_params(row, rng, false), n, l, e));
  }
  // Grazing: the light (or the eye) at angle eps above the tangent plane of n = z, eps = 0 exactly
  // some of the time; l = e; l = -e; scaled and denormal vectors.
  for (int k = 0; k < 1000; ++k) {
    const double eps = std::array{0.0, 1e-3, 1e-6, 1e-9, 1e-12}[rng() % 5];
    const double phi = u(0, 6.283185307179586), phi2 = u(0, 6.283185307179586);
    Vec3<double> n{0, 0, 1}, l{fl(std::cos(phi)), fl(std::sin(phi)), fl(eps)}, e{fl(std::cos(phi2)), fl(std::sin(phi2)), fl(u(0.01, 1))};
    switch (k % 6) {
      case 0: break;                                   // grazing light
      case 1: std::swap(l, e); break;                  // grazing eye
      case 2: e = {fl(-l.x), fl(-l.y), fl(eps)}; break;  // both grazing, l and e nearly opposite
      case 3: e = l = {l.x, l.y, fl(u(0.01, 1))}; break;  // l = e
      case 4: e = {fl(-l.x), fl(-l.y), fl(-l.z)}; break;  // l = -e (below the horizon: h undefined)
      case 5: {                                        // lengths from 1e-30 to 1e14, or denormal in double
        const double s = k % 12 == 5 ? 1e-310 : std::pow(10.0, double(int(rng() % 45) - 30));
        n = dir(1), l = flip_into(dir(1), n, true), e = flip_into(dir(1), n, true);
        n = {n.x * s, n.y * s, n.z * s};
        if (k % 12 == 11) l = {l.x * 1e12, l.y * 1e12, l.z * 1e12};
        break;
      }
    }
    hard.inputs.push_back(make(random_params(row, rng, true), n, l, e));
  }
  return {random, hard};
}

}  // namespace sw::lighting_io
