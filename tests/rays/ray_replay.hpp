// The replay of the ray-plane, ray-box and ray-sphere step tests: the inputs (the catalog
// example, the lessons, the corpus, the generated random and hard sets, and seeded small-rational
// cases that reach every miss line), the expected outcome held against the oracle and against what
// the algorithm returned, and the loop that matches every recorded step to its expectation.
#pragma once
#include <catch2/catch.hpp>
#include <functional>
#include "catalog.hpp"
#include "ray_steps.hpp"
#include "rays/cases.hpp"
#include "rays_oracle.hpp"

namespace sw::testing::rays {

struct Outcome {
  bool hit = false;
  Val t;
  Q t_near, t_far;
};

inline Outcome hit_at(const Val& t) {
  Outcome o;
  o.hit = true, o.t = t;
  return o;
}

inline VV at(const Parsed& p, const Val& t) { return lift(p.o) + t * lift(p.d); }
inline ExpectedStep& scene_ray(ExpectedStep& s, const Parsed& p) { return s.item2(GeoKind::ray3, lift(p.o), lift(p.d)).keep(); }

// Seeded small-rational inputs: parallel rays, origins on the primitive, zero direction
// components, flat boxes, tangents and origins on the sphere come up often.
inline std::vector<Case> small_cases(const std::string& prim, int count, std::uint64_t seed) {
  SmallRng g(seed);
  std::vector<Case> out;
  for (int k = 0; k < count; ++k) {
    Json in;
    if (prim == "plane") {
      in = {{"ray", {{"o", g.vec(-2, 2)}, {"d", g.nonzero_vec(-2, 2, false)}}},
            {"plane", {{"p", g.vec(-2, 2)}, {"n", g.nonzero_vec(-1, 1, false)}}}};
    } else if (prim == "box") {
      Json lo = g.vec(-2, 1), hi = Json::array();
      for (int a = 0; a < 3; ++a) hi.push_back(Q(q(lo[a]) + g.pick(0, 2)).get_str());  // 0: a flat box
      Json d = Json::array();
      for (int a = 0; a < 3; ++a) d.push_back(g.one_in(3) ? Json("0") : g.num(-2, 2));
      if (d == Json::array({"0", "0", "0"})) d[0] = "1";
      in = {{"ray", {{"o", g.vec(-3, 3)}, {"d", d}}}, {"box", {{"min", lo}, {"max", hi}}}};
    } else {
      const Json c = g.vec(-2, 2);
      const Q r = std::array{Q(1), Q(2), Q(3), ratio(1, 2), ratio(5, 2)}[g.pick(0, 4)];
      Json o = g.vec(-4, 4);
      if (g.one_in(4)) {  // on the sphere: c + r u for a rational unit vector u
        static const Q units[][3] = {
            {1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {ratio(3, 5), ratio(4, 5), 0}, {ratio(2, 3), ratio(-2, 3), ratio(1, 3)}};
        const auto& u = units[g.pick(0, 4)];
        for (int a = 0; a < 3; ++a) o[a] = Q(q(c[a]) + r * u[a]).get_str();
      }
      in = {{"ray", {{"o", o}, {"d", g.nonzero_vec(-2, 2, false)}}}, {"sphere", {{"c", c}, {"r", r.get_str()}}}};
    }
    out.push_back({"small " + std::to_string(k), in});
  }
  return out;
}

inline std::vector<Case> all_cases(std::string_view id, const std::string& prim, std::uint64_t seed) {
  std::vector<Case> out = example_and_lessons(id);
  for (Case& c : corpus_cases(prim)) out.push_back(std::move(c));
  int n = 0;
  for (const Json& j : sw::rays::random_inputs(prim.c_str(), 60, seed)) out.push_back({"random " + std::to_string(n++), j});
  const auto hard = sw::rays::hard_inputs(prim.c_str(), 5);
  for (std::size_t i = 0; i < hard.size(); i += hard.size() / 40 + 1) out.push_back({"hard " + std::to_string(i), hard[i]});
  for (Case& c : small_cases(prim, 300, seed + 1)) out.push_back(std::move(c));
  return out;
}

// The expected outcome against the oracle, and what the algorithm returned against it.
inline void check_outcome(const std::string& prim, const Parsed& p, const Outcome& want, const Returned& got) {
  oracle::RayResult o = prim == "plane" ? oracle::ray_plane(p.o, p.d, p.v[0], p.v[1])
                        : prim == "box" ? oracle::ray_box(p.o, p.d, p.v[0], p.v[1])
                                        : oracle::ray_sphere(p.o, p.d, p.v[0], p.r);
  REQUIRE(o.hit == want.hit);
  CHECK(got.hit == want.hit);
  if (!want.hit) return;
  CHECK(matches(got.t, want.t));
  CHECK(got.t_exact == !want.t.approx);
  CHECK(o.t_exact == !want.t.approx);
  if (o.t_exact) CHECK(o.t == want.t.v);
  else CHECK(abs(Q(o.t - want.t.v)) <= abs(o.t) / Q(mpz_class(1) << 126));  // the oracle's t: 128 bits
  if (prim == "box") {
    CHECK(o.t_near == want.t_near);
    CHECK(o.t_far == want.t_far);
    CHECK(got.t_near == want.t_near);
    CHECK(got.t_far == want.t_far);
  }
}

using ExpectFn = Outcome (*)(const Parsed&, Expected&);

// Replays `id` on every case; returns the lines seen and calls `tally` with each case's outcome.
template <class Tally> inline std::set<std::string_view> replay(std::string_view id, const std::string& prim, ExpectFn expect,
                                                                std::uint64_t seed, Tally tally) {
  const auto cases = all_cases(id, prim, seed);
  CHECK(cases.size() >= 380);
  std::set<std::string_view> seen;
  for (const Case& c : cases) {
    INFO(id << ", " << c.name << ": " << c.input.dump());
    const Parsed p = parse(c.input, prim);
    Recorder<Q> t;
    const Returned got = record_direct(id, c.input, t);
    Expected want;
    const Outcome out = expect(p, want);
    require_matches(t, find_algorithm(id).listing, want, seen);
    check_outcome(prim, p, out, got);
    tally(p, out, want);
  }
  return seen;
}

inline std::uint32_t last_line(const Expected& e) { return e.steps.back().line; }

}  // namespace sw::testing::rays
