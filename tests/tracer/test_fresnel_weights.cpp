// The catalog's `whitted`, read step by step: at every surface the tracer splits, the mirror and
// transmitted rays' weights and the transmitted direction against formulas written here
// independently of algorithms/tracer/refraction.hpp:
//  - Fresnel's reflectance as the mean of the s- and p-polarised amplitudes squared,
//    rs = (n1 ci - n2 ct) / (n1 ci + n2 ct), rp = (n1 ct - n2 ci) / (n1 ct + n2 ci);
//  - wr = kr + kt F and wt = kt (1 - F);
//  - Snell's law in vector form, n1 (N x d) = n2 (N x T), with T a unit vector through the surface.
// The rays come from scenes/glass-spheres.json (glass: kr 1/10, kt 9/10, ior 1.5; water: kt 0.95,
// ior 1.33), over a grid of pixels that crosses both spheres, entering and leaving.
#include <catch2/catch.hpp>
#include <cmath>
#include <optional>
#include "catalog.hpp"
#include "tracer/history.hpp"
#include "tracer/render.hpp"

using namespace sw;

namespace {

using V3 = std::array<double, 3>;

V3 cross(const V3& a, const V3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 unit(const V3& a) {
  const double l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}

// Unpolarised Fresnel reflectance for a unit d meeting unit N (d.N < 0) from index n1 into n2.
double fresnel(const V3& d, const V3& n, double n1, double n2) {
  const double ci = -dot(d, n), s2 = (n1 / n2) * (n1 / n2) * (1 - ci * ci);
  if (s2 >= 1) return 1;
  const double ct = std::sqrt(1 - s2);
  const double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct), rp = (n1 * ct - n2 * ci) / (n1 * ct + n2 * ci);
  return (rs * rs + rp * rp) / 2;
}

V3 vec_var(const TraceView& t, const StepRecord& st, std::string_view name) {
  for (std::uint32_t v = st.var_begin; v < st.var_end; ++v)
    if (const VarRecord& r = t.var_at(v); std::string_view(r.name) == name)
      return {t.component_double(r, 0), t.component_double(r, 1), t.component_double(r, 2)};
  FAIL("no variable " << name);
  return {};
}

double num_var(const TraceView& t, const StepRecord& st, std::string_view name) {
  for (std::uint32_t v = st.var_begin; v < st.var_end; ++v)
    if (const VarRecord& r = t.var_at(v); std::string_view(r.name) == name) return t.value_double(r);
  FAIL("no variable " << name);
  return 0;
}

// The step's ray3 item: origin and direction.
std::optional<std::pair<V3, V3>> ray_item(const TraceView& t, const StepRecord& st) {
  for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g)
    if (const GeoRecord& r = t.geo_at(g); r.kind == GeoKind::ray3)
      return std::pair{V3{t.geo_double(r, 0), t.geo_double(r, 1), t.geo_double(r, 2)},
                       V3{t.geo_double(r, 3), t.geo_double(r, 4), t.geo_double(r, 5)}};
  return std::nullopt;
}

}  // namespace

TEST_CASE("whitted: every split's Fresnel weights and transmitted direction against independent formulas", "[tracer][refraction][whitted]") {
  const Json base = {{"scene", "scenes/glass-spheres.json"}, {"size", {80, 60}}};
  Json first = base;
  first["pixel"] = {0, 0};
  const tracer::HistoryInput parsed = tracer::parse_history_input(first);
  const tracer::TraceScene<double> ts = tracer::trace_scene(*parsed.scene, 80, 60);
  const Algorithm& alg = find_algorithm("whitted");
  std::size_t splits = 0, transmitted = 0, leaving = 0, total_reflections = 0;
  // Every pixel's trace rebuilds the scene's photon map, so the grid is sparse: 13 x 12 pixels.
  for (int j = 2; j < 60; j += 5)
    for (int i = 2; i < 80; i += 6) {
      Json in = base;
      in["pixel"] = {i, j};
      const Recorded rec = alg.open(in, Numeric::f64).record();
      const TraceView& t = *rec.trace;
      // Per open ray, innermost last: its direction, then the surface it met.
      struct Level {
        V3 d{}, n{};
        bool entering = false;
        std::int64_t object = -1;
        double f = 0;
        bool tir = true;
      };
      std::vector<Level> open;
      for (std::size_t s = 0; s < t.size(); ++s) {
        const StepRecord& st = t.at(s);
        if (st.scope != 0 && t.scope_id(st.scope) != tracer::Whitted::id) continue;
        INFO("pixel (" << i << ", " << j << ") step " << s);
        using L = tracer::Whitted;
        switch (st.line) {
          case L::closest: {
            Level lv;
            lv.object = std::int64_t(num_var(t, st, "object"));
            for (std::uint32_t g = st.geo_begin; g < st.geo_end; ++g) {
              const GeoRecord& r = t.geo_at(g);
              const V3 a{t.geo_double(r, 0), t.geo_double(r, 1), t.geo_double(r, 2)}, b{t.geo_double(r, 3), t.geo_double(r, 4), t.geo_double(r, 5)};
              if (r.kind == GeoKind::segment3) lv.d = unit({b[0] - a[0], b[1] - a[1], b[2] - a[2]});
              if (r.kind == GeoKind::ray3) lv.d = unit(b);
              if (r.kind == GeoKind::segment3 || r.kind == GeoKind::ray3) break;
            }
            open.push_back(lv);
            break;
          }
          case L::surface:
            open.back().n = unit(vec_var(t, st, "N"));
            open.back().entering = num_var(t, st, "entering") != 0;
            break;
          case L::split: {
            Level& lv = open.back();
            const auto& m = ts.materials[std::size_t(ts.objects[std::size_t(lv.object)].material)];
            REQUIRE(m.shading.params.fresnel == lighting::Fresnel::exact);
            const double n1 = lv.entering ? 1 : m.ior, n2 = lv.entering ? m.ior : 1;
            lv.f = num_var(t, st, "F"), lv.tir = num_var(t, st, "tir") != 0;
            CHECK(lv.f == Approx(fresnel(lv.d, lv.n, n1, n2)).margin(1e-12));
            ++splits, leaving += !lv.entering, total_reflections += lv.tir;
            break;
          }
          case L::reflect:
          case L::transmit: {
            const Level& lv = open.back();
            const auto& m = ts.materials[std::size_t(ts.objects[std::size_t(lv.object)].material)];
            const auto ray = ray_item(t, st);
            REQUIRE(ray);
            const double w = *t.geo_value(t.geo_at(st.geo_begin));
            if (st.line == L::reflect) {
              CHECK(w == Approx(m.kr + m.kt * lv.f).margin(1e-12));
              break;
            }
            CHECK(w == Approx(m.kt * (1 - lv.f)).margin(1e-12));
            REQUIRE_FALSE(lv.tir);
            // Snell: n1 (N x d) = n2 (N x T); T unit and on the far side of the surface.
            const double n1 = lv.entering ? 1 : m.ior, n2 = lv.entering ? m.ior : 1;
            const V3 tt = ray->second, a = cross(lv.n, lv.d), b = cross(lv.n, tt);
            CHECK(dot(tt, tt) == Approx(1).margin(1e-12));
            CHECK(dot(tt, lv.n) < 0);
            for (int k = 0; k < 3; ++k) CHECK(n1 * a[k] == Approx(n2 * b[k]).margin(1e-12));
            ++transmitted;
            break;
          }
          case L::background:
          case L::deep:
          case L::done: open.pop_back(); break;
          default: break;
        }
      }
    }
  // The grid meets both spheres and enters and leaves them. (A ray inside a sphere meets its
  // surface at the angle it entered at, so none of these is total internal reflection: the TIR
  // cases are test_refraction.cpp's.)
  INFO(splits << " splits, " << transmitted << " transmitted, " << leaving << " leaving");
  CHECK(splits > 80);
  CHECK(transmitted > 80);
  CHECK(leaving > 60);
  CHECK(total_reflections == 0);
}
