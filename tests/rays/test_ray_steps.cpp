// The ray family's exact step replay (every variable against a closed form) and `check` on exact
// traces.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <sys/wait.h>
#include "catalog.hpp"
#include "ray_test_support.hpp"
#include "rays/cases.hpp"
#include "rays_oracle.hpp"
#include "trace_io.hpp"
#include "rays/ray_box.hpp"
#include "rays/ray_plane.hpp"
#include "rays/ray_sphere_geometric.hpp"
#include "rays/ray_sphere_quadratic.hpp"
#include "rays/ray_sphere_stable.hpp"
#include "rays/ray_triangle_barycentric.hpp"
#include "rays/ray_triangle_mt.hpp"
#include "rays/ray_triangle_watertight.hpp"

using namespace sw;
using namespace sw::testing::rays;

TEST_CASE("rays: exact step replay, every variable", "[rays]") {
  std::vector<std::pair<std::string, Json>> inputs;
  for (const Json& c : read_jsonl("corpus.jsonl")) inputs.push_back({c["primitive"], c["input"]});
  for (const char* prim : {"triangle", "sphere", "box", "plane"}) {
    for (const Json& j : rays::random_inputs(prim, 60, 99)) inputs.push_back({prim, j});
    const auto hard = rays::hard_inputs(prim, 5);
    for (std::size_t i = 0; i < hard.size(); i += hard.size() / 40 + 1) inputs.push_back({prim, hard[i]});
  }
  std::size_t checked = 0;
  for (const auto& [prim, in] : inputs) {
    const Parsed p = parse(in, prim);
    const V3 f = sub(p.o, p.v[0]);
    for (const std::string& id : kAlgs.at(prim)) {
      const Recorded rec = find_algorithm(id).record(in, Numeric::exact);
      const auto& tr = dynamic_cast<const Recorder<Rational>&>(*rec.trace);
      INFO(id << " " << in.dump());
      // Integer state the expected values depend on, read as the steps go.
      std::map<std::string, std::int64_t> ints;
      Rational tn, tf;
      bool bounded = false;
      for (std::size_t s = 0; s < tr.size(); ++s) {
        const StepRecord& st = tr.at(s);
        for (auto vi = st.var_begin; vi < st.var_end; ++vi) {
          const VarRecord& var = tr.var_at(vi);
          const std::string name = var.name;
          if (var.is_int) {
            ints[name] = tr.int_value(var.slot);
            continue;
          }
          const Rational got = tr.num_value(var.slot);
          std::optional<Rational> want;
          bool approx = false;  // went through a rounded square root
          if (prim == "triangle") {
            const V3 e1 = sub(p.v[1], p.v[0]), e2 = sub(p.v[2], p.v[0]), so = sub(p.o, p.v[0]);
            const V3 a = sub(p.v[0], p.o), b = sub(p.v[1], p.o), c = sub(p.v[2], p.o);
            const Rational w0 = oracle::triple(p.d, b, c), w1 = oracle::triple(p.d, c, a), w2 = oracle::triple(p.d, a, b);
            if (id == "ray-triangle-watertight") {
              const int kx = int(ints["kx"]), ky = int(ints["ky"]), kz = int(ints["kz"]);
              const Rational adz = abs(p.d[kz]);
              auto sheared = [&](const V3& v, int k) { return Rational(v[k] - p.d[k] / p.d[kz] * v[kz]); };
              const std::map<std::string, Rational> m = {
                  {"Sx", p.d[kx] / p.d[kz]}, {"Sy", p.d[ky] / p.d[kz]}, {"Sz", 1 / p.d[kz]},
                  {"Ax", sheared(a, kx)}, {"Ay", sheared(a, ky)}, {"Bx", sheared(b, kx)}, {"By", sheared(b, ky)},
                  {"Cx", sheared(c, kx)}, {"Cy", sheared(c, ky)},
                  // The shear frame (kx, ky, kz) is an even permutation when d_kz > 0 and odd
                  // otherwise, so the 2D edge functions are -(triple products) / |d_kz|.
                  {"U", -w0 / adz}, {"V", -w1 / adz}, {"W", -w2 / adz}, {"det", -(w0 + w1 + w2) / adz},
                  {"T", -oracle::triple(e1, e2, a) / adz}};
              if (m.count(name)) want = m.at(name);
            } else if (id == "ray-triangle-mt") {
              const Rational det = oracle::triple(e1, p.d, e2);
              const std::map<std::string, Rational> m = {{"det", det}};
              if (m.count(name)) want = m.at(name);
              if (sgn(det) != 0) {
                if (name == "u") want = oracle::triple(so, p.d, e2) / det;
                if (name == "v") want = oracle::triple(p.d, so, e1) / det;
                if (name == "t") want = oracle::triple(e2, so, e1) / det;
              }
            } else {
              const V3 n = crossq(e1, e2);
              const Rational den = oracle::triple(p.d, e1, e2);
              if (name == "nx") want = oracle::triple(kAxis[0], e1, e2);
              if (name == "ny") want = oracle::triple(kAxis[1], e1, e2);
              if (name == "nz") want = oracle::triple(kAxis[2], e1, e2);
              if (name == "den") want = den;
              if (name == "t") want = dotq(n, a) / den;
              if (name == "beta") want = w1 / (w0 + w1 + w2);
              if (name == "gamma") want = w2 / (w0 + w1 + w2);
            }
            if (name == "b0") want = w0 / (w0 + w1 + w2);
            if (name == "b1") want = w1 / (w0 + w1 + w2);
            if (name == "b2") want = w2 / (w0 + w1 + w2);
            if (name == "t" && !want) want = oracle::ray_triangle(p.o, p.d, p.v).t;
          } else if (prim == "sphere") {
            const Rational a = dotq(p.d, p.d), r2 = p.r * p.r, fxd2 = dotq(crossq(f, p.d), crossq(f, p.d));
            const Rational cc = dotq(f, f) - r2, hb = dotq(f, p.d);
            const std::map<std::string, Rational> m = {
                {"L2", dotq(f, f)}, {"a", a}, {"r2", r2}, {"tca", -hb}, {"m2", fxd2 / a}, {"h2", a * r2 - fxd2},
                {"b", 2 * hb}, {"c", cc}, {"b'", hb}, {"lx", f.x - hb / a * p.d.x}, {"ly", f.y - hb / a * p.d.y},
                {"lz", f.z - hb / a * p.d.z}};
            if (m.count(name)) want = m.at(name);
            if (name == "D") want = id == "ray-sphere-quadratic" ? Rational(4 * (a * r2 - fxd2)) : Rational(a * r2 - fxd2);
            // Roots: they must satisfy Vieta's formulas with the other recorded root (checked below).
            if (name == "t0" || name == "t1" || name == "n0" || name == "n1" || name == "near" || name == "far" || name == "q") approx = true;
            if (name == "t") {
              const auto o = oracle::ray_sphere(p.o, p.d, p.v[0], p.r);
              REQUIRE(o.hit);
              want = o.t;
              approx = !o.t_exact;  // rational t: exact equality
            }
          } else if (prim == "box") {
            const int k = int(ints["k"]);
            if (sgn(p.d[k]) != 0) {
              Rational t1 = (p.v[0][k] - p.o[k]) / p.d[k], t2 = (p.v[1][k] - p.o[k]) / p.d[k];
              if (t1 > t2) std::swap(t1, t2);
              if (name == "t1") want = t1;
              if (name == "t2") {
                want = t2;
                tn = bounded ? std::max(tn, t1) : t1, tf = bounded ? std::min(tf, t2) : t2, bounded = true;
              }
            }
            if (name == "t_near") want = tn;
            if (name == "t_far") want = tf;
            if (name == "t") want = oracle::ray_box(p.o, p.d, p.v[0], p.v[1]).t;
          } else {
            const Rational den = dotq(p.v[1], p.d);
            if (name == "den") want = den;
            if (name == "num") want = dotq(p.v[1], sub(p.v[0], p.o));
            if (name == "t") want = dotq(p.v[1], sub(p.v[0], p.o)) / den;
          }
          if (approx && name != "t") {
            ++checked;
            continue;  // checked as pairs after the loop
          }
          INFO("variable " << name << " at step " << s);
          REQUIRE(want.has_value());  // every recorded number has an independent expectation
          if (approx) CHECK(num::round_bits(got, oracle::kSphereTBits) == *want);
          else CHECK(got == *want);
          ++checked;
        }
      }
      // Sphere roots recorded as pairs: Vieta (t0 t1 = c/a, t0 + t1 = -b/a) on the exact inputs, and
      // the quadratic's numerators n = 2a t.
      if (prim == "sphere") {
        std::map<std::string, Rational> v;
        for (std::size_t s = 0; s < tr.size(); ++s)
          for (auto vi = tr.at(s).var_begin; vi < tr.at(s).var_end; ++vi)
            if (!tr.var_at(vi).is_int) v[tr.var_at(vi).name] = tr.num_value(tr.var_at(vi).slot);
        const Rational a = dotq(p.d, p.d), cc = dotq(f, f) - p.r * p.r, hb = dotq(f, p.d);
        for (auto [x, y] : {std::pair{"t0", "t1"}, std::pair{"near", "far"}})
          if (v.count(x)) {
            CHECK(close(v[x] * v[y], cc / a));
            CHECK(close(v[x] + v[y], -2 * hb / a));
          }
        if (v.count("n0")) {  // n0 n1 = b^2 - D = 4 a cc, n0 + n1 = -2b
          CHECK(close(v["n0"] * v["n1"], 4 * a * cc));
          CHECK(close(v["n0"] + v["n1"], -4 * hb));
        }
        if (v.count("q")) CHECK(close((v["q"] + hb) * (v["q"] + hb), Rational(a * p.r * p.r - dotq(crossq(f, p.d), crossq(f, p.d)))));
      }
    }
  }
  CHECK(checked > 2000);
}

TEST_CASE("rays: stepwise check accepts exact traces and rejects a tampered one", "[rays]") {
  for (const Json& c : read_jsonl("corpus.jsonl"))
    for (const std::string& id : kAlgs.at(c["primitive"])) {
      std::stringstream ss;
      write_trace(find_algorithm(id), Numeric::exact, c["input"], ss);
      const CheckReport rep = check_trace(ss, false);
      INFO(id << " " << c["name"].get<std::string>() << ": " << rep.message);
      CHECK(rep.status == 0);
    }
  std::stringstream ss;
  const Json in = Json::parse(R"({"ray":{"o":[0,0,5],"d":[0,0,-1]},"sphere":{"c":[0,0,0],"r":1}})");
  write_trace(find_algorithm("ray-sphere-stable"), Numeric::exact, in, ss);
  std::string text = ss.str();
  const auto pos = text.find("\"t\":\"4\"");
  REQUIRE(pos != std::string::npos);
  text.replace(pos, 7, "\"t\":\"5\"");
  std::stringstream bad(text);
  CHECK(check_trace(bad, false).status == 1);
}
