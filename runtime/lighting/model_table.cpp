#include "lighting/model_table.hpp"
#include <algorithm>

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

}  // namespace sw::lighting_io
