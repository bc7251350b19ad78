#include "lighting/lighting_input.hpp"
#include <algorithm>
#include <cmath>
#include "lighting/model_table.hpp"

namespace sw::lighting_io {

using namespace sw::lighting;

Vec3<Rational> direction3(const Json& obj, const char* key, const std::string& what) {
  const Json& v = require(obj, key, what);
  const std::string w = what + "." + key;
  if (!v.is_array() || v.size() != 3) throw InputError(w + ": expected an array of 3 numbers");
  Vec3<Rational> p;
  for (int k = 0; k < 3; ++k) {
    const std::string wk = w + "[" + std::to_string(k) + "]";
    p[k] = parse_rational(v[k], wk);
    check_bound(p[k], kCoordBound, wk);
  }
  if (sgn(p.x) == 0 && sgn(p.y) == 0 && sgn(p.z) == 0) throw InputError(w + ": zero-length direction");
  return p;
}

Rational number_in(const Json& obj, const char* key, const Rational& lo, const Rational& hi, bool lo_open, const std::string& what) {
  const std::string w = what + "." + key;
  const Rational x = parse_rational(require(obj, key, what), w);
  check_digits(x, w);
  if (x < lo || x > hi || (lo_open && x == lo))
    throw InputError(w + ": " + x.get_str() + " is outside " + (lo_open ? "(" : "[") + lo.get_str() + ", " + hi.get_str() + "]");
  return x;
}

Fresnel parse_fresnel(const Json& v, const std::string& what) {
  if (v.is_string()) {
    const std::string s = v.get<std::string>();
    if (s == "exact") return Fresnel::exact;
    if (s == "schlick") return Fresnel::schlick;
    if (s == "one") return Fresnel::one;
    throw InputError(what + ": unknown Fresnel term '" + s + "' (exact, schlick, one)");
  }
  throw InputError(what + ": expected \"exact\", \"schlick\" or \"one\"");
}

ModelInput parse_model_input(std::string_view id, const Json& j) {
  if (!j.is_object()) throw InputError("input: expected an object");
  const ModelRow& row = model_row(id);
  ModelInput in;
  in.choice = row.choice;
  std::vector<const ModelParam*> params;
  std::vector<std::string_view> keys = {"n", "l", "e"}, optional;
  if (row.toon) {
    const ModelRow& inner = diffuse_row(require(j, "diffuse", "input"), "input.diffuse");
    in.choice.diffuse = inner.choice.diffuse;
    keys.push_back("diffuse");
    params = inner.params;
  }
  params.insert(params.end(), row.params.begin(), row.params.end());
  for (const ModelParam* p : params) keys.push_back(p->key);
  if (row.fresnel) keys.push_back("fresnel"), optional.push_back("shadowing");
  for (auto it = j.begin(); it != j.end(); ++it)
    if (std::find(keys.begin(), keys.end(), it.key()) == keys.end() && std::find(optional.begin(), optional.end(), it.key()) == optional.end())
      throw InputError("input: unknown field \"" + it.key() + "\" for " + std::string(id));
  for (std::string_view k : keys) (void)require(j, std::string(k).c_str(), "input");
  for (const ModelParam* p : params) p->set(in.p, number_in(j, std::string(p->key).c_str(), Rational(p->lo), Rational(p->hi), p->lo_open, "input"));
  if (row.fresnel) {
    in.p.fresnel = parse_fresnel(j["fresnel"], "input.fresnel");
    if (j.contains("shadowing")) {
      if (!j["shadowing"].is_boolean()) throw InputError("input.shadowing: expected true or false");
      in.p.shadowing = j["shadowing"].get<bool>();
    }
  }
  in.n = direction3(j, "n", "input");
  in.l = direction3(j, "l", "input");
  in.e = direction3(j, "e", "input");
  decide(in);
  return in;
}

namespace {

// sign(alpha sqrt(x) + gamma), x >= 0, exactly: against the other sign, compare the squares.
int sign_root(const Rational& alpha, const Rational& x, const Rational& gamma) {
  const int sa = sgn(x) == 0 ? 0 : sgn(alpha), sg = sgn(gamma);
  if (sa == 0 || sg == 0 || sa == sg) return sa != 0 ? sa : sg;
  return sa * sgn(Rational(alpha * alpha * x - gamma * gamma));
}

// sign(alpha sqrt(x) + beta sqrt(y) + gamma), x, y >= 0, exactly. p = alpha sqrt(x) + beta sqrt(y)
// has a sign by the same rule; against gamma of the other sign, p^2 - gamma^2 = alpha^2 x + beta^2 y
// - gamma^2 + 2 alpha beta sqrt(x y) has one root.
int sign_roots(const Rational& alpha, const Rational& x, const Rational& beta, const Rational& y, const Rational& gamma) {
  const int sa = sgn(x) == 0 ? 0 : sgn(alpha), sb = sgn(y) == 0 ? 0 : sgn(beta);
  const int sp = sa == 0 || sb == 0 || sa == sb ? (sa != 0 ? sa : sb) : sa * sgn(Rational(alpha * alpha * x - beta * beta * y));
  const int sg = sgn(gamma);
  if (sp == 0 || sg == 0 || sp == sg) return sp != 0 ? sp : sg;
  return sp * sign_root(2 * alpha * beta, Rational(x * y), Rational(alpha * alpha * x + beta * beta * y - gamma * gamma));
}

// Oren-Nayar's d >= c exactly, on the raw vectors (lit and seen: N.L, N.E > 0). With unit cosines
// a = n.l, b = n.e and g = l.e - ab, d = a A (g <= 0), a A + B g (a >= b), a A + B a g / b (a < b),
// each multiplied out by a positive factor into a sum of square roots of rationals:
//   g <= 0:  A NL - c sqrt(NN LL) >= 0
//   a >= b:  A NL sqrt(NN EE) - c NN sqrt(LL EE) + B (LE NN - NL NE) >= 0     (times NN sqrt(LL EE))
//   a < b:   A NL NE sqrt(NN LL) + B NL (LE NN - NL NE) - c NN LL NE >= 0      (times NN LL NE)
// with NL = N.L, NN = N.N and so on. A and B are the model's rationals in sigma^2.
bool oren_nayar_above(const ModelInput& in, const Rational& c) {
  const Rational s2 = in.p.sigma * in.p.sigma;
  const Rational A = 1 - Rational(1, 2) * s2 / (s2 + Rational(33, 100)), B = Rational(45, 100) * s2 / (s2 + Rational(9, 100));
  const Rational NL = dot(in.n, in.l), NE = dot(in.n, in.e), LE = dot(in.l, in.e);
  const Rational NN = dot(in.n, in.n), LL = dot(in.l, in.l), EE = dot(in.e, in.e);
  const Rational G = LE * NN - NL * NE;  // g times NN sqrt(LL EE)
  if (sgn(G) <= 0) return sign_root(-c, Rational(NN * LL), Rational(A * NL)) >= 0;
  if (NL * NL * EE >= NE * NE * LL) return sign_roots(A * NL, Rational(NN * EE), -c * NN, Rational(LL * EE), Rational(B * G)) >= 0;
  return sign_root(A * NL * NE, Rational(NN * LL), Rational(B * NL * G - c * NN * LL * NE)) >= 0;
}

}  // namespace

void decide(ModelInput& in) {
  in.signs = frame_signs(in.n, in.l, in.e);
  in.p.toon_above.reset();
  if (!in.p.toon || !(in.signs.lit && in.signs.seen)) return;
  const Rational& c = *in.p.toon;
  const bool lambert_like = in.choice.diffuse == DiffuseModel::lambert || (in.choice.diffuse == DiffuseModel::minnaert && in.p.minnaert_k == 1) ||
                            (in.choice.diffuse == DiffuseModel::oren_nayar && sgn(in.p.sigma) == 0);
  if (lambert_like) {  // n.l >= c  <=>  (N.L)^2 >= c^2 (N.N)(L.L), given N.L > 0 and c >= 0
    const Rational nl = dot(in.n, in.l);
    in.p.toon_above = nl * nl >= c * c * dot(in.n, in.n) * dot(in.l, in.l);
    return;
  }
  if (in.choice.diffuse == DiffuseModel::oren_nayar) {
    in.p.toon_above = oren_nayar_above(in, c);
    return;
  }
  // Minnaert with k != 1: (n.l)^k (n.e)^(k-1) with k a rational of up to 64-bit terms is not a
  // polynomial sign; decided on the 300-bit reference value (docs/lighting/semantics.md).
  NoProbe none;
  const Frame<Rational> f = shading_frame<Toon>(in.n, in.l, in.e, none, in.signs);
  in.p.toon_above = !(diffuse_nested(in.choice.diffuse, f, in.p, none) < c);
}

Json to_json(const ModelInput& in) {
  auto v = [](const Vec3<Rational>& x) { return Json::array({x.x.get_str(), x.y.get_str(), x.z.get_str()}); };
  Json j = {{"n", v(in.n)}, {"l", v(in.l)}, {"e", v(in.e)}};
  const auto& p = in.p;
  // The row of the entry: toon when a cut is set, else the chosen term's own row.
  const ModelRow* row = nullptr;
  for (const ModelRow& r : model_table())
    if (r.toon == p.toon.has_value() && (r.toon || (r.choice.specular == in.choice.specular && (in.choice.specular ? r.choice.spec == in.choice.spec : r.choice.diffuse == in.choice.diffuse))))
      row = &r;
  if (!row) throw std::logic_error("to_json: no model row");
  std::vector<const ModelParam*> params = row->params;
  if (row->toon) {
    j["diffuse"] = std::string(model_name(in.choice.diffuse));
    for (const ModelRow& r : model_table())
      if (!r.choice.specular && !r.toon && r.choice.diffuse == in.choice.diffuse) params.insert(params.end(), r.params.begin(), r.params.end());
  }
  for (const ModelParam* q : params) j[std::string(q->key)] = q->get(p).get_str();
  if (row->fresnel) {
    j["fresnel"] = p.fresnel == Fresnel::exact ? "exact" : p.fresnel == Fresnel::schlick ? "schlick" : "one";
    if (!p.shadowing) j["shadowing"] = false;
  }
  return j;
}

}  // namespace sw::lighting_io
