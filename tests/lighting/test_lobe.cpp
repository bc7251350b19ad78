// The reflection models' lobe view, their sliders and two models side by side: every lobe sample
// is the model at an eye direction in the plane of incidence as the CLI computes it; the
// reference lobes peak where the physics says (Blinn-Phong and Phong at the mirror direction,
// Lambert flat); every slider's range is valid input; and a second model runs on the carried
// input, side by side in the app with a shared scale.
#ifdef SW_HAVE_VISUALIZER
#include <catch2/catch.hpp>
#include <cmath>
#include "lessons/compare.hpp"
#include "headless/headless.hpp"
#include "panels/lobe_view.hpp"

using namespace sw;
using namespace sw::vis;

namespace {

const char* kModels[] = {"lambert", "minnaert", "oren-nayar", "toon", "phong", "blinn-phong", "gaussian", "beckmann", "cook-torrance"};

std::array<double, 3> vec(const Json& j) { return {parse_rational(j[0], "v").get_d(), parse_rational(j[1], "v").get_d(), parse_rational(j[2], "v").get_d()}; }
double dot3(const std::array<double, 3>& a, const std::array<double, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double len(const std::array<double, 3>& a) { return std::sqrt(dot3(a, a)); }

// The grid the lobe view uses, coarser: every 5 degrees from -90 to 90.
SweepGrid lobe_grid(Numeric n) { return SweepGrid{37, 1, 0, 0, 5, 1, n == Numeric::f32 ? Numeric::f32 : Numeric::f64}; }

}  // namespace

TEST_CASE("lobe: every direction is the model at that eye, in the plane of incidence, as the CLI computes it", "[lighting][lobe][views]") {
  for (const char* id : kModels) {
    const Algorithm& alg = find_algorithm(id);
    REQUIRE(alg.lobe);
    REQUIRE(alg.lobe.sample);
    REQUIRE(std::find(alg.views.begin(), alg.views.end(), View::lobe) != alg.views.end());
    Json input = parse_json_text(alg.example, "example");
    input["l"] = {2, 1, 3};  // a light off the axes: the plane is not a coordinate plane
    const auto n = vec(input["n"]), l = vec(input["l"]);
    for (Numeric mode : {Numeric::f32, Numeric::f64, Numeric::reference}) {
      const SweepGrid g = lobe_grid(mode);
      std::vector<float> out;
      alg.open(input, mode).lobe(g, out);
      REQUIRE(out.size() == 37);
      for (int i = 0; i < g.w; ++i) {
        const Json sample = alg.open(input).lobe_sample(g, i);
        const auto e = vec(sample["e"]);
        INFO(id << " " << numeric_name(mode) << " at " << g.x(i) << " degrees: " << sample.dump());
        CHECK(std::fabs(len(e) - 1) < 1e-6);
        // In the plane of n and l: e . (n x l) = 0.
        const std::array<double, 3> b{n[1] * l[2] - n[2] * l[1], n[2] * l[0] - n[0] * l[2], n[0] * l[1] - n[1] * l[0]};
        CHECK(std::fabs(dot3(e, b)) < 1e-6 * len(b));
        // At angle x(i) from the normal, on the side away from the light for positive angles.
        CHECK(std::fabs(std::acos(std::clamp(dot3(e, n) / len(n), -1.0, 1.0)) * 180 / 3.141592653589793 - std::fabs(g.x(i))) < 1e-4);
        const double side = dot3(e, l) - dot3(e, n) * dot3(n, l) / dot3(n, n);  // e's tangent part along l's
        if (std::fabs(g.x(i)) > 1) CHECK((side < 0) == (g.x(i) > 0));
        CHECK(out[std::size_t(i)] == static_cast<float>(alg.open(sample, mode).run()["value"].get<double>()));
      }
    }
  }
}

TEST_CASE("lobe: the reference lobes of Phong and Blinn-Phong peak at the mirror direction and Lambert's is flat", "[lighting][lobe]") {
  const Json base = parse_json_text(R"({"n":[0,0,3],"l":[1,0,1],"e":[0,0,1]})", "t");  // the light at 45 degrees
  const SweepGrid g{181, 1, 0, 0, 1, 1, Numeric::f64};  // every degree
  for (const char* id : {"phong", "blinn-phong"}) {
    Json in = base;
    in["shininess"] = 30;
    std::vector<float> out;
    find_algorithm(id).open(in, Numeric::reference).lobe(g, out);
    const auto top = std::size_t(std::max_element(out.begin(), out.end()) - out.begin());
    INFO(id);
    CHECK(g.x(int(top)) == 45);
    CHECK(out[top] == Approx(1).epsilon(1e-6));
    CHECK(out[90] < out[top]);  // the normal direction is dimmer
    const auto angles = find_algorithm(id).open(in).lobe_angles();
    REQUIRE(angles);
    CHECK((*angles)[0] == Approx(-45));  // the light, on the other side
    CHECK((*angles)[1] == Approx(0).margin(1e-9));
  }
  std::vector<float> flat;
  find_algorithm("lambert").open(base, Numeric::reference).lobe(g, flat);
  for (std::size_t i = 1; i + 1 < flat.size(); ++i) CHECK(flat[i] == Approx(std::sqrt(0.5)).epsilon(1e-7));
  // A denormal normal and a huge light give the same plane, and the same flat lobe.
  const Json scaled = parse_json_text(R"({"n":[0,0,1e-310],"l":[1e14,0,1e14],"e":[0,0,1]})", "t");
  std::vector<float> flat2;
  find_algorithm("lambert").open(scaled, Numeric::reference).lobe(g, flat2);
  CHECK(flat2 == flat);
  CHECK((*find_algorithm("lambert").open(scaled).lobe_angles())[0] == Approx(-45));
  // An eye off the plane has no angle.
  Json off = base;
  off["e"] = {0, 1, 1};
  CHECK(std::isnan((*find_algorithm("lambert").open(off).lobe_angles())[1]));
}

TEST_CASE("sliders: every declared parameter's range is valid input where the example has it", "[lighting][params]") {
  std::size_t checked = 0;
  for (const Algorithm& alg : catalog()) {
    std::vector<Json> inputs{parse_json_text(alg.example, "example")};
    if (alg.id == "toon") {
      inputs.push_back(parse_json_text(R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"diffuse":"minnaert","k":0.5,"cutoff":0.5})", "t"));
      inputs.push_back(parse_json_text(R"({"n":[0,0,1],"l":[1,0,1],"e":[0,1,2],"diffuse":"oren-nayar","sigma":0.5,"cutoff":0.5})", "t"));
    }
    for (const Param& p : alg.params)
      for (Json in : inputs) {
        const Json::json_pointer ptr(p.pointer);
        if (!in.contains(ptr)) continue;
        for (double v : {p.lo, p.hi, p.logarithmic ? std::sqrt(std::max(p.lo, 1e-3) * p.hi) : (p.lo + p.hi) / 2}) {
          in[ptr] = v;
          INFO(alg.id << " " << p.pointer << " = " << v);
          for (Numeric n : alg.numerics) CHECK_NOTHROW((void)alg.open(in, n));
          ++checked;
        }
      }
  }
  CHECK(checked >= 30);
  CHECK(find_algorithm("phong").params.size() >= 1);
  CHECK(find_algorithm("shade").params.size() >= 1);
}

TEST_CASE("two models: the comparison names a number type or a model of the group, and the model runs on the carried input", "[lighting][compare]") {
  const Algorithm& phong = find_algorithm("phong");
  const Comparison c = parse_comparison(phong, "blinn-phong", Numeric::f64);
  REQUIRE(c.other);
  CHECK(c.other->id == "blinn-phong");
  CHECK(c.label() == "blinn-phong (double)");
  CHECK(parse_comparison(phong, "float", Numeric::f64).numeric == Numeric::f32);
  CHECK(parse_comparison(phong, "float", Numeric::f64).other == nullptr);
  try {
    (void)parse_comparison(phong, "dda-line", Numeric::f64);
    FAIL("dda-line accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("cook-torrance") != std::string::npos);  // the error lists the group
  }
  CHECK_THROWS_AS(parse_comparison(find_algorithm("dda-line"), "phong", Numeric::f64), InputError);
  const Json left = parse_json_text(R"({"n":[0,0,1],"l":[1,0,1],"e":[-1,0,2],"shininess":7})", "t");
  const Json carried = carried_input(left, parse_json_text(find_algorithm("cook-torrance").example, "example"));
  CHECK(carried["n"] == left["n"]);
  CHECK(carried["e"] == left["e"]);
  CHECK_FALSE(carried.contains("shininess"));  // not one of Cook-Torrance's keys
  CHECK(carried.contains("ior"));

  // In the app: the right canvas runs Beckmann on Phong's vectors; Blinn-Phong carries the exponent too.
  HeadlessHost host(1280, 800);
  App& app = host.app();
  Session& session = app.session();
  REQUIRE(session.open_algorithm(phong, left, Numeric::f64, Comparison(Numeric::f64, &find_algorithm("blinn-phong"))));
  REQUIRE(session.model(1));
  CHECK(session.model(1)->algorithm().id == "blinn-phong");
  CHECK(session.model(1)->input()["shininess"] == 7);
  CHECK(session.model(1)->input()["e"] == left["e"]);
  REQUIRE(session.open_algorithm(phong, left, Numeric::f64, Comparison(Numeric::f64, &find_algorithm("beckmann"))));
  REQUIRE(session.set_view(View::lobe));
  host.render(3);
  const auto* a = dynamic_cast<const LobeCanvas*>(app.canvas(0));
  const auto* b = dynamic_cast<const LobeCanvas*>(app.canvas(1));
  REQUIRE(a);
  REQUIRE(b);
  CHECK(a->lobe().samples() == std::size_t(LobeCanvas::kDirections));
  CHECK(a->lobe().disagreements() == 0);  // double against the reference, at 1/255
  // Beckmann's lobe peaks far above Phong's 1; side by side both use one scale: pixels per unit
  // of the term are the same in both canvases.
  const std::size_t mirror = (LobeCanvas::kDirections - 1) / 2 + 90;  // +45 degrees, every half degree
  CHECK(a->lobe().grid.x(int(mirror)) == 45);
  const float va = a->lobe().mode[mirror], vb = b->lobe().mode[mirror];
  REQUIRE(vb > 2 * va);
  const ImVec2 pa = a->sample_point(mirror), pb = b->sample_point(mirror);
  const float ra = std::hypot(pa.x - a->centre().x, pa.y - a->centre().y), rb = std::hypot(pb.x - b->centre().x, pb.y - b->centre().y);
  CHECK(ra > 10);
  CHECK(ra / va == Approx(rb / vb).epsilon(0.01));
}
#endif
