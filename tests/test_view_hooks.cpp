// The view hooks Specs declare (runtime/views.hpp): the exact curves' outlines lie on the curves,
// marching squares finds a circle, the sweep runs what the CLI runs on the very sample inputs,
// every declared view and table line exists, every result key a view reads is declared (and every
// declared key is in the results), and the scene view's picture, pick and summary table.
#include <catch2/catch.hpp>
#include <cmath>
#include "catalog.hpp"
#include "contour.hpp"
#include "lessons/result_keys.hpp"

using namespace sw;

namespace {

// Every vertex lies within `tol` of the circle (cx, cy, r), and the vertices visit all 72 five-degree
// sectors of it.
void check_on_circle(const std::vector<Polyline2>& lines, double cx, double cy, double r, double tol) {
  REQUIRE(!lines.empty());
  std::vector<bool> sector(72, false);
  for (const Polyline2& l : lines)
    for (const auto& p : l) {
      const double dx = p[0] - cx, dy = p[1] - cy;
      INFO("vertex (" << p[0] << ", " << p[1] << ")");
      CHECK(std::fabs(std::hypot(dx, dy) - r) <= tol);
      sector[static_cast<std::size_t>(std::floor((std::atan2(dy, dx) + M_PI) / (2 * M_PI) * 72)) % 72] = true;
    }
  CHECK(std::count(sector.begin(), sector.end(), true) == 72);
}

}  // namespace

TEST_CASE("view hooks: marching squares on x^2 + y^2 - 25 stays within 1e-3 of the circle of radius 5", "[views][outline]") {
  const auto f = [](double x, double y) { return x * x + y * y - 25; };
  check_on_circle(contour(f, {-8, -7, 8, 7}, 0.1), 0, 0, 5, 1e-3);
  // A window wholly inside or outside the circle has no contour.
  CHECK(contour(f, {-1, -1, 1, 1}, 0.1).empty());
  CHECK(contour(f, {6, 6, 9, 9}, 0.1).empty());
}

TEST_CASE("view hooks: implicit-curve and circle-midpoint outline their exact circles", "[views][outline]") {
  const Json implicit = parse_json_text(R"({"P":[[1,2,0],[1,0,2],[-25,0,0]],"start":[-5,0],"max_steps":100})", "t");
  check_on_circle(find_algorithm("implicit-curve").open(implicit).outline({-8, -8, 8, 8}, 0.05), 0, 0, 5, 1e-3);
  const Json circle = parse_json_text(R"({"c":[3,-2],"r":40})", "t");
  check_on_circle(find_algorithm("circle-midpoint").open(circle).outline({-60, -60, 60, 60}, 0.5), 3, -2, 40, 1e-2);
  // Zoomed far in on a large circle, the outline is still on it (a chord would not be).
  const Json big = parse_json_text(R"({"c":[0,0],"r":4000000})", "t");
  const auto lines = find_algorithm("circle-interior").open(big).outline({3999990, -5, 4000010, 5}, 0.02);
  REQUIRE(!lines.empty());
  for (const auto& l : lines)
    for (const auto& p : l) CHECK(std::fabs(std::hypot(p[0], p[1]) - 4000000) <= 1e-3);
}

TEST_CASE("view hooks: the cubic's outline is y = P(x) on the plotted columns, the Bezier's ends at its end points", "[views][outline]") {
  for (const char* id : {"poly-forward-diff", "poly-horner"}) {
    const Json in = parse_json_text(R"({"coeffs":["1/64",0,"-3/2",2],"xs":-12,"xe":13})", "t");
    const auto lines = find_algorithm(id).open(in).outline({-100, -100, 100, 100}, 0.25);
    REQUIRE(lines.size() == 1);
    CHECK(lines[0].front()[0] == -12);
    CHECK(lines[0].back()[0] == 12);
    for (const auto& p : lines[0]) {
      const Rational x = num::to_rational(p[0]);
      const Rational y = Rational(1, 64) * x * x * x - Rational(3, 2) * x + 2;
      CHECK(std::fabs(p[1] - y.get_d()) <= 1e-12);
    }
    // Only the visible columns are sampled.
    const auto part = find_algorithm(id).open(in).outline({0, -100, 5, 100}, 0.25);
    REQUIRE(part.size() == 1);
    CHECK(part[0].front()[0] == 0);
    CHECK(part[0].back()[0] == 5);
  }
  const Json b = parse_json_text(R"({"bezier":[[0.5,0],[3,"29/4"],[9.5,"-5/3"],[12,6]],"n":6})", "t");
  const auto lines = find_algorithm("bezier-forward-diff").open(b).outline({0, 0, 1, 1}, 0.1);
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].front() == std::array<double, 2>{0.5, 0});
  CHECK(lines[0].back() == std::array<double, 2>{12, 6});
}

TEST_CASE("view hooks: every sample of a ray sweep is what the CLI computes on the sample's input", "[views][sweep]") {
  const Json in = parse_json_text(R"({"ray":{"o":[0,0,10],"d":[0.30458447,0.30458447,-0.9024725]},"sphere":{"c":[1,2,0],"r":3}})", "t");
  for (const char* id : {"ray-sphere-quadratic", "ray-box", "ray-plane", "ray-triangle-watertight"}) {
    const Algorithm& alg = find_algorithm(id);
    REQUIRE(alg.sweep);
    REQUIRE(alg.sweep.sample);
    Json input = parse_json_text(alg.example, "example");
    if (std::string_view(id) == "ray-sphere-quadratic") input = in;
    for (Numeric n : {Numeric::f32, Numeric::f64, Numeric::exact}) {
      SweepGrid g{9, 7, 0.1, -0.2, 0.21, 0.27, n == Numeric::f32 ? Numeric::f32 : Numeric::f64};
      std::vector<float> out;
      alg.open(input, n).sweep(g, out);
      REQUIRE(out.size() == 63);
      for (int j = 0; j < g.h; ++j)
        for (int i = 0; i < g.w; ++i) {
          const Json sample = alg.open(input).sweep_sample(g, i, j);
          const Json r = alg.open(sample, n).run();
          INFO(id << " " << numeric_name(n) << " sample " << sample.dump());
          CHECK(r["hit"].get<bool>() == !std::isnan(out[std::size_t(j) * g.w + i]));
        }
    }
  }
}

TEST_CASE("view hooks: the middle sample of a window centred on the marker is the input itself", "[views][sweep]") {
  const Algorithm& alg = find_algorithm("ray-triangle-mt");
  const Json in = parse_json_text(alg.example, "example");
  const auto m = alg.open(in).sweep_marker();
  REQUIRE(m);
  const SweepGrid g{5, 5, (*m)[0], (*m)[1], 1e-3, 1e-3, Numeric::f64};
  const Json s = alg.open(in).sweep_sample(g, 2, 2);
  for (int k = 0; k < 3; ++k) {
    CHECK(parse_rational(s["ray"]["o"][k], "o") == parse_rational(in["ray"]["o"][k], "o"));
    CHECK(parse_rational(s["ray"]["d"][k], "d") == parse_rational(in["ray"]["d"][k], "d"));
  }
}

TEST_CASE("view hooks: declared views and table lines", "[views]") {
  for (const Algorithm& a : catalog()) {
    INFO(a.id);
    REQUIRE(!a.views.empty());
    for (std::string_view line : a.table_lines) CHECK(a.listing.find(line) != 0);
    const bool table = std::find(a.views.begin(), a.views.end(), View::table) != a.views.end();
    const bool image = std::find(a.views.begin(), a.views.end(), View::image) != a.views.end();
    if (image) CHECK(a.sweep);
    if (!a.table_lines.empty()) CHECK(table);
  }
  CHECK(find_algorithm("poly-forward-diff").table_lines == std::vector<std::string_view>{"start", "step"});
  for (std::size_t k = 0; k < kViewNames.size(); ++k) CHECK(parse_view(kViewNames[k]) == static_cast<View>(k));
  CHECK_FALSE(parse_view("forest"));
}

TEST_CASE("view hooks: every sample of a shading sweep is the model on the sphere's normal there, as the CLI computes it", "[views][sweep]") {
  for (const char* id : {"lambert", "minnaert", "oren-nayar", "toon", "phong", "blinn-phong", "gaussian", "beckmann", "cook-torrance"}) {
    const Algorithm& alg = find_algorithm(id);
    REQUIRE(alg.sweep);
    REQUIRE(alg.sweep.shaded);
    const Json input = parse_json_text(alg.example, "example");
    for (Numeric n : {Numeric::f32, Numeric::f64, Numeric::reference}) {
      SweepGrid g{9, 7, 0.05, -0.1, 0.25, 0.3, n == Numeric::f32 ? Numeric::f32 : Numeric::f64};
      std::vector<float> out;
      alg.open(input, n).sweep(g, out);
      REQUIRE(out.size() == 63);
      std::size_t on = 0;
      for (int j = 0; j < g.h; ++j)
        for (int i = 0; i < g.w; ++i) {
          const float v = out[std::size_t(j) * g.w + i];
          const double x = g.x(i), y = g.y(j);
          INFO(id << " " << numeric_name(n) << " sample " << i << ", " << j);
          if (x * x + y * y >= 1) {  // off the sphere: no value
            CHECK(std::isnan(v));
            continue;
          }
          ++on;
          const Json sample = alg.open(input).sweep_sample(g, i, j);
          CHECK(sample["n"][2].get<double>() > 0);
          CHECK(v == static_cast<float>(alg.open(sample, n).run()["value"].get<double>()));
        }
      CHECK(on > 20);
    }
  }
}

TEST_CASE("view hooks: every result key a view reads is declared by the algorithms it reads it from", "[views][result_keys]") {
  for (const Algorithm& alg : catalog()) {
    INFO(alg.id);
    // Declared keys are in the results: the example's in each mode.
    for (Numeric n : alg.numerics) {
      INFO(numeric_name(n));
      Json r;
      try {
        r = alg.open(parse_json_text(alg.example, "example"), n).run();
      } catch (const InputError&) {
        continue;  // the example is not this mode's input (fractions in int mode)
      }
      for (std::string_view key : alg.result_keys) CHECK(r.contains(std::string(key)));
      // The keys views read: declared where they must be, and wherever the results have them.
      for (const vis::ResultRead* read : vis::result_reads::all) {
        if (!read->reads_from(alg)) continue;
        INFO(read->reader << " reads '" << read->key << "'");
        if (read->required || r.contains(std::string(read->key))) CHECK(alg.declares_result(read->key));
      }
    }
  }
  // The reads as the views make them: nothing from an undeclared key.
  const Algorithm& dda = find_algorithm("dda-line");
  const auto m = vis::record_model(dda, parse_json_text(dda.example, "example"), Numeric::exact);
  CHECK_FALSE(vis::read_result(*m, vis::result_reads::strip_hit));
  const Algorithm& box = find_algorithm("ray-box");
  const auto b = vis::record_model(box, parse_json_text(box.example, "example"), Numeric::exact);
  REQUIRE(vis::read_result(*b, vis::result_reads::strip_hit));
  CHECK(vis::read_result(*b, vis::result_reads::strip_hit)->is_boolean());
}

TEST_CASE("view hooks: the scene view's picture, pick and summary table come from the Spec", "[views][scene]") {
  for (const Algorithm& alg : catalog()) {
    INFO(alg.id);
    const bool scene = std::find(alg.views.begin(), alg.views.end(), View::scene) != alg.views.end();
    CHECK(bool(alg.picture) == scene);  // the scene view draws the picture, its notes and the summary
    CHECK(alg.summary_table == scene);
    if (!scene) CHECK_THROWS_AS(alg.open(parse_json_text(alg.example, "example")).picture(8), std::logic_error);
  }
  const Algorithm& whitted = find_algorithm("whitted");
  CHECK(whitted.picture.pick == "/pixel");
  const Json input = parse_json_text(whitted.example, "example");
  const auto opened = inputs_opened();
  const Run run = whitted.open(input, Numeric::f64);
  const Picture p = run.picture(40);     // 80x60 at most 40 a side: every other pixel
  CHECK(inputs_opened() - opened == 1);  // the picture is made from the opened input: no re-read
  CHECK(p.scale == 2);
  CHECK(p.width == 40);
  CHECK(p.height == 30);
  CHECK(p.rgb.size() == 3 * 40 * 30);
  CHECK(p.notes_title == "Planner");
  CHECK(!p.notes.empty());
  for (const Picture::Note& n : p.notes) CHECK((n.on.has_value() && !n.why.empty()));
  // The summary of a recorded trace: a row per ray, each ray that returned with its colours, and
  // the shares summing to the pixel's colour.
  const Recorded rec = run.record();
  const SummaryTable t = run.summary_table(*rec.trace);
  CHECK(t.title == "Ray tree");
  CHECK(t.columns == std::vector<std::string>{"ray", "depth", "kind", "weight", "found", "share"});
  REQUIRE(t.rows.size() >= 2);
  CHECK(t.rows[0].cells[2].text == "primary");
  std::size_t coloured = 0;
  for (const SummaryTable::Row& row : t.rows) {
    REQUIRE(row.cells.size() == t.columns.size());
    CHECK(row.step <= row.end);
    CHECK(row.end < rec.trace->size());
    coloured += row.cells[5].rgb.has_value();
  }
  CHECK(coloured >= 2);  // the chrome sphere and what its mirror ray finds
  REQUIRE(t.total);
  REQUIRE(t.total->cells[5].rgb);
  const Json& c = rec.result["colour"];
  for (std::size_t k = 0; k < 3; ++k) CHECK((*t.total->cells[5].rgb)[k] == Approx(c[k].get<double>()).margin(1e-12));
  CHECK(c[0].get<double>() + c[1].get<double>() + c[2].get<double>() > 0.1);  // not black: the colours are there
}
