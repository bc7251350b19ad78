// The ray intersection Specs' parts that depend on no algorithm: input parsing, the oracle's
// output, the bench sets and the sweep frame.
#include "rays/ray_spec.hpp"
#include <random>
#include "rays/cases.hpp"

namespace sw::rays {

RayInput parse_input(const Json& j, Prim prim) {
  static const char* names[] = {"triangle", "sphere", "box", "plane"};
  const char* key = names[static_cast<int>(prim)];
  if (prim == Prim::triangle && j.is_object() && j.contains("attr")) {
    Json rest = j;
    rest.erase("attr");
    only_keys(rest, {"ray", key}, "input");
  } else {
    only_keys(j, {"ray", key}, "input");
  }
  RayInput in;
  const Json& ray = j["ray"];
  only_keys(ray, {"o", "d"}, "input.ray");
  in.o = point3(ray["o"], "input.ray.o");
  in.d = point3(ray["d"], "input.ray.d", &in.d_neg_zero);
  if (sgn(in.d.x) == 0 && sgn(in.d.y) == 0 && sgn(in.d.z) == 0) throw InputError("input.ray.d: the direction is zero");
  const Json& g = j[key];
  switch (prim) {
    case Prim::triangle: {
      if (!g.is_array() || g.size() != 3) throw InputError("input.triangle: expected [[x,y,z],[x,y,z],[x,y,z]]");
      for (int i = 0; i < 3; ++i) in.v[i] = point3(g[i], "input.triangle[" + std::to_string(i) + "]");
      // A degenerate (zero-area) triangle is valid input and a defined miss (docs/rays/semantics.md).
      if (j.contains("attr")) {
        // Per-vertex attributes (uv, normals, colours...): three arrays of one length, 1..16.
        const Json& a = j["attr"];
        if (!a.is_array() || a.size() != 3) throw InputError("input.attr: expected three arrays, one per vertex");
        for (int i = 0; i < 3; ++i) {
          const std::string what = "input.attr[" + std::to_string(i) + "]";
          if (!a[i].is_array() || a[i].empty() || a[i].size() > 16 || a[i].size() != a[0].size())
            throw InputError(what + ": expected 1 to 16 numbers, as many as for every vertex");
          for (std::size_t k = 0; k < a[i].size(); ++k) {
            in.attr[i].push_back(parse_rational(a[i][k], what + "[" + std::to_string(k) + "]"));
            check_bound(in.attr[i].back(), kCoordBound, what);
          }
        }
      }
      break;
    }
    case Prim::sphere:
      only_keys(g, {"c", "r"}, "input.sphere");
      in.v[0] = point3(g["c"], "input.sphere.c");
      in.r = parse_rational(g["r"], "input.sphere.r");
      check_bound(in.r, kCoordBound, "input.sphere.r");
      if (sgn(in.r) <= 0) throw InputError("input.sphere.r: the radius must be > 0, got " + in.r.get_str());
      break;
    case Prim::box:
      only_keys(g, {"min", "max"}, "input.box");
      in.v[0] = point3(g["min"], "input.box.min");
      in.v[1] = point3(g["max"], "input.box.max");
      for (int k = 0; k < 3; ++k)
        if (in.v[0][k] > in.v[1][k]) throw InputError("input.box: min[" + std::to_string(k) + "] > max[" + std::to_string(k) + "]");
      break;
    case Prim::plane:
      only_keys(g, {"p", "n"}, "input.plane");
      in.v[0] = point3(g["p"], "input.plane.p");
      in.v[1] = point3(g["n"], "input.plane.n");
      if (sgn(in.v[1].x) == 0 && sgn(in.v[1].y) == 0 && sgn(in.v[1].z) == 0) throw InputError("input.plane.n: the normal is zero");
      break;
  }
  return in;
}

RayOutput from_oracle(const Exact& e) {
  RayOutput o;
  o.hit = e.hit;
  o.exact = std::make_shared<Exact>(e);
  return o;
}

Json number_json(double d, const Rational* q) { return q ? Json(q->get_str()) : Json(d); }

std::vector<BenchSet<RayInput>> bench_sets_for(Prim p) {
  static const char* names[] = {"triangle", "sphere", "box", "plane"};
  const char* name = names[static_cast<int>(p)];
  BenchSet<RayInput> random{"random", {}}, hard{"hard", {}};
  for (const Json& j : rays::random_inputs(name, 10000, 20261122)) random.inputs.push_back(parse_input(j, p));
  for (const Json& j : rays::hard_inputs(name, 20261123)) hard.inputs.push_back(parse_input(j, p));
  return {random, hard};
}

double round_to(Numeric n, double x) { return n == Numeric::f32 ? double(float(x)) : x; }

SweepFrame sweep_frame(const RayInput& in, Prim prim, Numeric inputs) {
  SweepFrame f;
  std::array<double, 3> o, d;
  for (int k = 0; k < 3; ++k) o[k] = in.o[k].get_d(), d[k] = in.d[k].get_d();
  for (int k = 0; k < 3; ++k)
    if (std::fabs(d[k]) > std::fabs(d[f.m])) f.m = k;
  f.a = (f.m + 1) % 3, f.b = (f.m + 2) % 3, f.flip = d[f.m] < 0 ? 1 : -1;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  auto add = [&](const Vec3<Rational>& q, double pad) {  // q's shadow along d, grown by pad
    const double t = (q[f.m].get_d() - o[f.m]) / d[f.m];
    const double p[2] = {q[f.a].get_d() - t * d[f.a], q[f.b].get_d() - t * d[f.b]};
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k] - pad), hi[k] = std::max(hi[k], p[k] + pad);
  };
  const double stretch = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / std::fabs(d[f.m]);
  switch (prim) {
    case Prim::triangle: for (const auto& v : in.v) add(v, 0); break;
    case Prim::sphere: add(in.v[0], in.r.get_d() * stretch); break;
    case Prim::box:
      for (int c = 0; c < 8; ++c) add({in.v[c & 1].x, in.v[(c >> 1) & 1].y, in.v[c >> 2].z}, 0);
      break;
    case Prim::plane: add(in.o, std::max(1.0, std::sqrt(dot(in.o - in.v[0], in.o - in.v[0]).get_d()))); break;
  }
  f.ca = (lo[0] + hi[0]) / 2, f.cb = (lo[1] + hi[1]) / 2;
  f.s = std::max(hi[0] - lo[0], hi[1] - lo[1]) / 2 * 1.15;
  if (!(f.s > 0) || !std::isfinite(f.s)) f.s = 1;
  for (int k = 0; k < 3; ++k) f.o[k] = round_to(inputs, o[k]), f.d[k] = in.d_neg_zero[k] ? -0.0 : round_to(inputs, d[k]);
  f.mx = (o[f.a] - f.ca) / f.s * f.flip, f.my = (o[f.b] - f.cb) / f.s;
  return f;
}

// input ray.
std::array<double, 3> sample_origin(const SweepFrame& f, const SweepGrid& g, int i, int j) {
  std::array<double, 3> o = f.o;
  o[f.a] = round_to(g.inputs, f.o[f.a] + f.flip * (g.x(i) - f.mx) * f.s);
  o[f.b] = round_to(g.inputs, f.o[f.b] + (g.y(j) - f.my) * f.s);
  return o;
}

}  // namespace sw::rays
