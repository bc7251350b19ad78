// The declared views beyond plane2d and orbit3d: the table view's rows and columns are the recorded
// values, its highlight follows the step and a click jumps; the image view counts exactly the
// disagreements an independent exact oracle finds and paints them; the plane2d canvas draws the
// exact curve; `stepwise render --view` renders a chosen view.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <cmath>
#include "cli_harness.hpp"
#include "headless/headless.hpp"
#include "host_pixels.hpp"
#include "panels/image_view.hpp"
#include "lighting_oracle.hpp"
#include "panels/outline_layer.hpp"
#include "panels/plot_view.hpp"
#include "rays_oracle.hpp"
#include "panels/table_view.hpp"

using namespace sw;
using namespace sw::vis;
using sw::testing::channel_distance;
using sw::testing::kHostH;
using sw::testing::kHostW;

namespace {

int blue_minus_red(std::uint32_t c) { return int((c >> 16) & 255) - int(c & 255); }
// The median of blue minus red at nine points across a row (some fall on a glyph).
int row_blueness(const HeadlessHost& host, const std::array<float, 4>& r) {
  std::vector<int> v;
  const int y = int(std::lround((r[1] + r[3]) / 2));
  for (int k = 1; k <= 9; ++k) v.push_back(blue_minus_red(host.pixel(int(r[0] + (r[2] - r[0]) * 0.095f * float(k)), y)));
  std::nth_element(v.begin(), v.begin() + 4, v.end());
  return v[4];
}

Rational cubic(const Rational& x) { return Rational(1, 64) * x * x * x - Rational(3, 2) * x + 2; }

const char* kCubic = R"({"coeffs":["1/64",0,"-3/2",2],"xs":-12,"xe":13})";
// Lesson 05's ray: exactly on the triangle's diagonal edge; float's u comes out just below 0.
const char* kEdgeRay = R"({"ray":{"o":[-1.9140625,1.91796875,11.66015625],"d":[5.49609375,1.6640625,-11.66015625]},"triangle":[[-5,-5,0],[5,-5,0],[5,5,0]]})";

}  // namespace

TEST_CASE("views table: poly-forward-diff's rows are x, y, j, d1, d2 of the cubic at each integer x", "[visualizer][views]") {
  const auto m = record_model(find_algorithm("poly-forward-diff"), parse_json_text(kCubic, "t"), Numeric::exact);
  const StepTable t = build_step_table(*m);
  REQUIRE(t.columns == std::vector<std::string_view>{"x", "y", "j", "d1", "d2"});
  REQUIRE(t.rows.size() == 26);  // the start, then one row per step of x (the last moves x to xe = 13)
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const Rational x(-12 + static_cast<long>(r));
    const std::vector<TableCell> c = table_row(*m, t, r);
    INFO("row " << r << " x = " << x.get_str());
    CHECK(c[0].text == x.get_str());
    CHECK(c[1].text == num::to_text(cubic(x)));
    CHECK(c[3].text == num::to_text(cubic(x + 1) - cubic(x)));                       // the first difference
    CHECK(c[4].text == num::to_text(cubic(x + 2) - 2 * cubic(x + 1) + cubic(x)));    // the second
    if (x < 13) CHECK(c[2].text == std::to_string(num::floor_int(Rational(cubic(x) + Rational(1, 2)))));
    CHECK(c[0].recorded);
    CHECK(c[3].recorded == (r > 0));  // the start row carries d1 and d2 from the table step
  }
  CHECK(t.row_of(0) == std::nullopt);
  CHECK(t.row_of(t.rows[3]) == 3u);
  CHECK(t.row_of(t.rows[3] + 1) == 3u);
  CHECK(t.row_of(m->last()) == t.rows.size() - 1);
}

TEST_CASE("views table: poly-horner has one row per column and circle-midpoint one per octant pixel", "[visualizer][views]") {
  const auto h = record_model(find_algorithm("poly-horner"), parse_json_text(kCubic, "t"), Numeric::f64);
  const StepTable th = build_step_table(*h);
  CHECK(th.columns == std::vector<std::string_view>{"x", "y", "j"});
  CHECK(th.rows.size() == 25);
  const auto c = record_model(find_algorithm("circle-midpoint"), parse_json_text(R"({"c":[0,0],"r":9})", "t"), Numeric::integer);
  const StepTable tc = build_step_table(*c);
  CHECK(tc.rows.size() == 7);  // y = 0 .. 6 in the octant y <= -x of r = 9
  for (std::size_t r = 0; r < tc.rows.size(); ++r) CHECK(table_row(*c, tc, r)[1].text == std::to_string(r));  // column y
}

TEST_CASE("views table: the highlighted row follows the step, is drawn highlighted, and a click jumps to its step", "[visualizer][views][render]") {
  HeadlessHost host(kHostW, kHostH);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_algorithm(find_algorithm("poly-forward-diff"), parse_json_text(R"({"coeffs":[1,-3,0,5],"xs":-40,"xe":40})", "t"), Numeric::f32));
  REQUIRE(session.set_view(View::table));
  CHECK_FALSE(session.set_view(View::image));  // not declared
  const TraceModel& m = *session.model(0);
  for (std::size_t step : {std::size_t(0), std::size_t(4), std::size_t(5), std::size_t(77), std::size_t(150), m.last()}) {
    session.set_step(step);
    host.render();
    const auto* tc = dynamic_cast<const TableCanvas*>(app.canvas(0));
    REQUIRE(tc);
    INFO("step " << step);
    REQUIRE(tc->highlighted_row() == tc->table().row_of(step));
    if (!tc->highlighted_row()) continue;
    const auto rect = tc->row_rect(*tc->highlighted_row());
    REQUIRE(rect);  // scrolled into view
    CHECK(row_blueness(host, *rect) >= 40);
    // The rows drawn next to it are not highlighted.
    for (std::size_t other : {*tc->highlighted_row() - 1, *tc->highlighted_row() + 1})
      if (const auto o = tc->row_rect(other)) CHECK(std::abs(row_blueness(host, *o)) < 25);
  }
  // A click on another drawn row goes to that row's first step.
  session.set_step(60);
  host.render();
  const auto* tc = dynamic_cast<const TableCanvas*>(app.canvas(0));
  const std::size_t target = *tc->highlighted_row() + 2;
  const auto rect = tc->row_rect(target);
  REQUIRE(rect);
  const ImVec2 at(((*rect)[0] + (*rect)[2]) / 2, ((*rect)[1] + (*rect)[3]) / 2);
  host.set_mouse(at, true);
  host.render(1);
  host.set_mouse(at, false);
  host.render(1);
  CHECK(session.step() == tc->table().rows[target]);
  CHECK(session.view() == View::table);
}

TEST_CASE("views plot: table_values holds every cell of table_row, carried values included", "[visualizer][views]") {
  const std::pair<const char*, const char*> runs[] = {{"poly-forward-diff", kCubic},
                                                      {"circle-midpoint", R"({"c":[2,1],"r":12})"},
                                                      {"bezier-forward-diff", R"({"bezier":[[0.5,0],[3,"29/4"],[9.5,"-5/3"],[12,6]],"n":6})"},
                                                      {"implicit-curve", R"({"P":[["1/4",2,0],[1,0,2],[-36,0,0]],"start":[-12,0],"max_steps":40})"}};
  for (const auto& [id, input] : runs) {
    const auto m = record_model(find_algorithm(id), parse_json_text(input, "t"), Numeric::f64);
    const StepTable t = build_step_table(*m);
    const auto values = table_values(*m, t);
    REQUIRE(values.size() == t.columns.size());
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      const auto cells = table_row(*m, t, r);
      for (std::size_t c = 0; c < cells.size(); ++c) {
        INFO(id << " row " << r << " column " << t.columns[c]);
        if (cells[c].text.empty()) CHECK(std::isnan(values[c][r]));
        else CHECK(values[c][r] == cells[c].value);
      }
    }
  }
}

TEST_CASE("views plot: a float difference table's drift against exact, plotted and clickable", "[visualizer][views][render]") {
  HeadlessHost host(kHostW, kHostH);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_lesson(std::filesystem::path(SW_SOURCE_DIR) / "lessons/08-forward-difference-drift.md"));
  REQUIRE(session.set_view(View::plot));
  host.render(3);
  const auto* pc = dynamic_cast<const PlotCanvas*>(app.canvas(0));
  REQUIRE(pc);
  REQUIRE(pc->difference());
  const TraceModel &f = *session.model(0), &e = *session.model(1);  // the lesson: float, compared with exact
  REQUIRE(f.numeric() == Numeric::f32);
  REQUIRE(e.numeric() == Numeric::exact);
  const StepTable t = build_step_table(f);
  const auto y = std::find(t.columns.begin(), t.columns.end(), "y") - t.columns.begin();
  CHECK(pc->column() == y);
  const auto fv = table_values(f, t), ev = table_values(e, build_step_table(e));
  REQUIRE(pc->values() == fv[y]);
  REQUIRE(pc->exact() == ev[y]);
  CHECK(std::fabs(fv[y].back() - ev[y].back()) > 0.01);  // float's y has drifted by the end
  // The current row's marker is drawn where the row is.
  const std::size_t row = *t.row_of(session.step());
  const int x = int(std::lround(pc->row_x(row)));
  auto yellow = [&](int px, int py) {
    const std::uint32_t c = host.pixel(px, py);
    return int(c & 255) > 150 && int((c >> 8) & 255) > 130 && int((c >> 16) & 255) < 110;
  };
  int marked = 0, elsewhere = 0;
  for (int yy = 220; yy < 360; yy += 10) {
    marked += yellow(x - 1, yy) || yellow(x, yy) || yellow(x + 1, yy);
    elsewhere += yellow(x - 20, yy) || yellow(x + 20, yy);
  }
  CHECK(marked >= 12);
  CHECK(elsewhere == 0);
  // A click goes to the row under the (whole-pixel) mouse.
  const float mx = std::floor(pc->row_x(40));
  const std::size_t target = std::size_t((mx - pc->row_x(0) + (pc->row_x(1) - pc->row_x(0)) / 2) / (pc->row_x(1) - pc->row_x(0)));
  host.set_mouse(ImVec2(mx, 300), true);
  host.render(1);
  host.set_mouse(ImVec2(mx, 300), false);
  host.render(1);
  CHECK(session.step() == t.rows[target]);
  CHECK(target >= 38);
  CHECK(target <= 40);
}

TEST_CASE("views image: a shaded float sweep differs from reference by over 1/255 exactly where the MPFR oracle says", "[visualizer][views]") {
  // Blinn-Phong with a huge exponent: float's c = n.h, raised to 2 * 10^5, loses the highlight's value.
  const Algorithm& alg = find_algorithm("blinn-phong");
  const Json input = parse_json_text(R"({"n":[0,0,1],"l":[1,0.5,2],"e":[-0.5,0.25,2],"shininess":200000})", "t");
  const auto m = record_model(alg, input, Numeric::f32);
  const SweepGrid g{61, 61, 0.1042, 0.1804, 0.0002, 0.0002, Numeric::f32};  // around the highlight, n = h
  const SweepImage img = sweep_image(*m, g);
  REQUIRE(img.shaded);
  REQUIRE(img.reference == Numeric::reference);
  REQUIRE(img.samples() == 61u * 61u);
  lighting::ModelParams<Rational> p;
  p.shininess = 200000;
  auto vec = [](const Json& j) { return Vec3<Rational>{parse_rational(j[0], "v"), parse_rational(j[1], "v"), parse_rational(j[2], "v")}; };
  std::size_t brighter = 0, darker = 0;
  for (int j = 0; j < g.h; ++j)
    for (int i = 0; i < g.w; ++i) {
      const Json s = alg.open(input).sweep_sample(g, i, j);
      const float ref = static_cast<float>(lighting_oracle::term({.specular = true, .spec = lighting::SpecularModel::blinn_phong}, vec(s["n"]), vec(input["l"]), vec(input["e"]), p).value.get_d());
      const float flt = static_cast<float>(alg.open(s, Numeric::f32).run()["value"].get<double>());
      const std::size_t k = std::size_t(j) * g.w + i;
      INFO("sample (" << i << ", " << j << ")");
      CHECK(std::fabs(img.exact[k] - ref) <= 1e-6f);
      CHECK(img.mode[k] == flt);
      const bool differs = std::fabs(flt - ref) > 1.f / 255;
      brighter += differs && flt > ref, darker += differs && flt < ref;
    }
  CHECK(img.false_hits == brighter);
  CHECK(img.missed == darker);
  CHECK(brighter + darker >= 10);  // float's error shows across the highlight
}

TEST_CASE("views image: a float ray-triangle sweep disagrees with exact exactly where the CGAL oracle says", "[visualizer][views]") {
  const Algorithm& alg = find_algorithm("ray-triangle-mt");
  const Json input = parse_json_text(kEdgeRay, "t");
  const auto m = record_model(alg, input, Numeric::f32);
  const auto marker = alg.open(input).sweep_marker();
  REQUIRE(marker);
  // 41 x 41 rays around the input ray, 2e-6 of the frame apart: across float's error band.
  const SweepGrid g{41, 41, (*marker)[0], (*marker)[1], 2e-6, 2e-6, Numeric::f32};
  const SweepImage img = sweep_image(*m, g);
  REQUIRE(img.samples() == 41u * 41u);
  std::array<Vec3<Rational>, 3> tri;
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k) tri[v][k] = parse_rational(input["triangle"][v][k], "v");
  std::size_t disagree = 0, false_hits = 0, hits = 0;
  for (int j = 0; j < g.h; ++j)
    for (int i = 0; i < g.w; ++i) {
      const Json s = alg.open(input).sweep_sample(g, i, j);
      Vec3<Rational> o, d;
      for (int k = 0; k < 3; ++k) o[k] = parse_rational(s["ray"]["o"][k], "o"), d[k] = parse_rational(s["ray"]["d"][k], "d");
      for (int k = 0; k < 3; ++k) REQUIRE(num::to_rational(double(float(o[k].get_d()))) == o[k]);  // float rays
      const bool exact = oracle::ray_triangle(o, d, tri).hit;
      const bool flt = alg.open(s, Numeric::f32).run()["hit"].get<bool>();
      const std::size_t k = std::size_t(j) * g.w + i;
      INFO("sample (" << i << ", " << j << ")");
      CHECK(exact == !std::isnan(img.exact[k]));
      CHECK(flt == !std::isnan(img.mode[k]));
      disagree += exact != flt, false_hits += flt && !exact, hits += exact;
    }
  CHECK(img.disagreements() == disagree);
  CHECK(img.false_hits == false_hits);
  CHECK(img.hits == hits);
  CHECK(disagree >= 8);  // the band shows (13 when measured)
  // The middle sample is the input ray: on the edge, a hit that float misses.
  CHECK(!std::isnan(img.exact[20 * 41 + 20]));
  CHECK(std::isnan(img.mode[20 * 41 + 20]));
  // Filtered mode is certified: no disagreement on the same grid.
  const auto f = record_model(alg, input, Numeric::filtered);
  CHECK(sweep_image(*f, g).disagreements() == 0);
}

TEST_CASE("views image: the headless render paints hits, misses and each disagreement in its colour", "[visualizer][views][render]") {
  HeadlessHost host(kHostW, kHostH);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_algorithm(find_algorithm("ray-triangle-mt"), parse_json_text(kEdgeRay, "t"), Numeric::f32));
  REQUIRE(session.set_view(View::image));
  host.render(3);
  app.jump_and_focus(session.steps() - 1);
  host.render(2);
  const auto* ic = dynamic_cast<const ImageCanvas*>(app.canvas(0));
  REQUIRE(ic);
  CHECK(ic->image().disagreements() == 1);  // the input ray itself, in the middle
  const auto centre = ic->sample_rect(ic->image().grid.w / 2, ic->image().grid.h / 2);
  // Zoom onto the input three times (Z over the canvas): float's error band shows.
  for (int k = 0; k < 3; ++k) {
    host.set_mouse(ImVec2((centre[0] + centre[2]) / 2, (centre[1] + centre[3]) / 2), false);
    host.type('z');
    host.render(2);
  }
  host.set_mouse(std::nullopt, false);
  host.render(2);
  const SweepImage& img = ic->image();
  REQUIRE(img.disagreements() >= 10);
  std::size_t checked = 0, coloured = 0, hit = 0, miss = 0;
  const SweepGrid& g = img.grid;
  for (int j = g.h / 4; j < g.h * 3 / 4; ++j)  // clear of the text plate and the legend
    for (int i = 0; i < g.w; ++i) {
      const std::size_t k = std::size_t(j) * g.w + i;
      const auto r = ic->sample_rect(i, j);
      const std::uint32_t px = host.pixel(int((r[0] + r[2]) / 2), int((r[1] + r[3]) / 2));
      const bool a = !std::isnan(img.mode[k]), e = !std::isnan(img.exact[k]);
      if (a != e) {
        ++checked;
        coloured += channel_distance(px, a ? kSweepFalseHit : kSweepMissed) <= 3;
      } else if (i % 7 == 0 && j % 7 == 0) {
        if (a) hit += blue_minus_red(px) >= 60;
        else miss += channel_distance(px, kSweepMissBoth) <= 3;
      }
    }
  CHECK(checked > 0);
  CHECK(coloured >= checked * 9 / 10);  // a few may sit under the input's cross or a ring
  CHECK(hit > 20);
  CHECK(miss > 20);
  // A click on a sample traces that sample's ray; the view stays.
  const auto r = ic->sample_rect(g.w / 4, g.h / 2);
  const ImVec2 at(std::floor((r[0] + r[2]) / 2), std::floor((r[1] + r[3]) / 2));
  const int i = int((at.x - ic->sample_rect(0, 0)[0]) / (r[2] - r[0])), j = int((at.y - ic->sample_rect(0, 0)[1]) / (r[3] - r[1]));
  const Json expected = session.model(0)->run().sweep_sample(g, i, j);
  host.set_mouse(at, true);
  host.render(1);
  host.set_mouse(at, false);
  host.render(1);
  CHECK(session.model(0)->input() == expected);
  CHECK(session.view() == View::image);
  // V shows the next declared view, and after the last the first.
  host.type('v');
  host.render(2);
  CHECK(session.view() == View::orbit3d);
  host.type('v');
  host.render(2);
  CHECK(session.view() == View::image);
}

TEST_CASE("views plane2d: the exact curve is drawn over the pixels of implicit-curve", "[visualizer][views][render]") {
  HeadlessHost host(kHostW, kHostH);
  App& app = host.app();
  REQUIRE(app.session().open_algorithm(find_algorithm("implicit-curve"), parse_json_text(R"({"P":[[1,2,0],[1,0,2],[-100,0,0]],"start":[-10,0],"max_steps":200})", "t"),
                             Numeric::exact));
  host.render(3);
  const auto c00 = app.canvas(0)->cell_rect({0, 0});
  REQUIRE(c00);
  const double scale = (*c00)[2] - (*c00)[0], sx = ((*c00)[0] + (*c00)[2]) / 2, sy = ((*c00)[1] + (*c00)[3]) / 2;
  int found = 0;
  for (int a = 0; a < 12; ++a) {
    const double th = (a + 0.5) * M_PI / 6;
    const int x = int(std::lround(sx + 10 * std::cos(th) * scale)), y = int(std::lround(sy - 10 * std::sin(th) * scale));
    bool near = false;
    for (int dx = -2; dx <= 2; ++dx)
      for (int dy = -2; dy <= 2; ++dy) near |= channel_distance(host.pixel(x + dx, y + dy), kOutline) <= 40;
    found += near;
  }
  CHECK(found >= 10);
  // Away from the circle (its centre), no outline.
  bool centre = false;
  for (int dx = -2; dx <= 2; ++dx)
    for (int dy = -2; dy <= 2; ++dy) centre |= channel_distance(host.pixel(int(sx) + dx, int(sy) + dy), kOutline) <= 40;
  CHECK_FALSE(centre);
}

TEST_CASE("views cli: stepwise render --view renders a declared view and refuses another", "[visualizer][views][cli]") {
  const auto dir = testing::scratch("views-cli");
  const auto png = dir / "table.png";
  auto ran = testing::run_stepwise("render --algorithm poly-horner --input " + testing::sh_quote(kCubic) + " --view table --step 7 --size 640x400 --out " +
                                   testing::sh_quote(png.string()));
  CHECK(ran.status == 0);
  CHECK(std::filesystem::file_size(png) > 1000);
  const auto bad = dir / "bad.png";
  ran = testing::run_stepwise("render --algorithm poly-horner --input " + testing::sh_quote(kCubic) + " --view image --out " + testing::sh_quote(bad.string()));
  CHECK(ran.status == 2);
  CHECK_THAT(ran.err, Catch::Contains("--view 'image'") && Catch::Contains("plane2d, table"));
  CHECK_FALSE(std::filesystem::exists(bad));
  std::filesystem::remove_all(dir);
}

#endif
