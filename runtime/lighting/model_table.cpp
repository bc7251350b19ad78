#include "lighting/model_table.hpp"
#include <algorithm>

namespace sw::lighting_io {

using lighting::DiffuseModel;
using lighting::ModelChoice;
using lighting::SpecularModel;
using P = lighting::ModelParams<Rational>;

namespace {

const ModelParam kK{"k", 0, 1, false, 0, 1, false, "Minnaert's darkening exponent: 1 is Lambert, lower darkens the limb less",
                    0, 1, {0, 1, 0.001, 0.999}, [](P& p, const Rational& x) { p.minnaert_k = x; }};
const ModelParam kSigma{"sigma", 0, 1, false, 0, 1, false, "Oren-Nayar's slope spread in radians: 0 is Lambert",
                        0, 1, {0, 1, 0.999}, [](P& p, const Rational& x) { p.sigma = x; }};
const ModelParam kCutoff{"cutoff", 0, 1, false, 0, 1, false, "toon: the diffuse value at which the band switches",
                         0, 1, {}, [](P& p, const Rational& x) { p.toon = x; }};
const ModelParam kShininess{"shininess", 0, 1e6, false, 0, 10000, true, "the highlight exponent n",
                            1, 200, {10000, 1000, 0, 1}, [](P& p, const Rational& x) { p.shininess = x; }};
const ModelParam kM{"m", 0, 100, true, 0.001, 1, true, "the RMS slope of the microfacets: lower is glossier",
                    0.05, 1, {0.001, 0.01, 1, 5}, [](P& p, const Rational& x) { p.m = x; }};
const ModelParam kIor{"ior", 1, 100, false, 1, 3, false, "the index of refraction in the Fresnel term",
                      1, 3, {1, 1.0001, 50}, [](P& p, const Rational& x) { p.ior = x; }};

constexpr ModelChoice diffuse(DiffuseModel m) { return {.specular = false, .diffuse = m}; }
constexpr ModelChoice specular(SpecularModel m) { return {.specular = true, .spec = m}; }

}  // namespace

const std::vector<ModelRow>& model_table() {
  static const std::vector<ModelRow> rows = {
      {"lambert", diffuse(DiffuseModel::lambert), {}, false, false, true, R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2]})"},
      {"minnaert", diffuse(DiffuseModel::minnaert), {&kK}, false, false, false, R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"k":0.5})"},
      {"oren-nayar", diffuse(DiffuseModel::oren_nayar), {&kSigma}, false, false, false, R"({"n":[0,0,1],"l":[1,0,1],"e":[1,1,2],"sigma":0.5})"},
      {"toon", diffuse(DiffuseModel::lambert), {&kCutoff}, true, false, false,
       R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"diffuse":"lambert","cutoff":0.5})"},
      {"phong", specular(SpecularModel::phong), {&kShininess}, false, false, true, R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0.25,2],"shininess":20})"},
      {"blinn-phong", specular(SpecularModel::blinn_phong), {&kShininess}, false, false, true,
       R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0.25,2],"shininess":20})"},
      {"gaussian", specular(SpecularModel::gaussian), {&kM}, false, false, true, R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0.25,2],"m":0.3})"},
      {"beckmann", specular(SpecularModel::beckmann), {&kM}, false, false, false, R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0.25,2],"m":0.3})"},
      {"cook-torrance", specular(SpecularModel::cook_torrance), {&kM, &kIor}, false, true, false,
       R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0.25,2],"m":0.3,"ior":1.5,"fresnel":"exact"})"},
  };
  return rows;
}

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
