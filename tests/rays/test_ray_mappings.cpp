// camera-ray and sphere-uv: pixel centres, projections, the seam and the poles.
#include <catch2/catch.hpp>
#include <cmath>
#include "catalog.hpp"
#include "ray_test_support.hpp"

using namespace sw;
using namespace sw::testing::rays;

TEST_CASE("rays: camera rays, pixel centres and projections", "[rays]") {
  const Algorithm& cam = find_algorithm("camera-ray");
  auto run = [&](const char* proj, int fov, int i, int j, int w, int h, Numeric n = Numeric::f64) {
    Json in = Json::parse(R"({"camera":{"eye":[1,2,3],"vpn":[0,0,2],"vup":[0,5,0],"d":2,"fov":90},"pixel":[0,0],"size":[1,1]})");
    in["projection"] = proj;
    in["camera"]["fov"] = fov;
    in["pixel"] = {i, j};
    in["size"] = {w, h};
    return cam.open(in, n).run();
  };
  for (const char* proj : {"perspective", "fisheye", "cylindrical"}) {
    // The centre pixel of an odd image looks straight along -n.
    const Json r = run(proj, 90, 2, 1, 5, 3);
    INFO(proj << " " << r.dump());
    REQUIRE(r["valid"].get<bool>());
    CHECK(std::fabs(r["d"][0].get<double>()) < 1e-15);
    CHECK(std::fabs(r["d"][1].get<double>()) < 1e-15);
    CHECK(r["d"][2].get<double>() < 0);
    CHECK(r["o"] == Json::array({1.0, 2.0, 3.0}));
  }
  // Perspective, 90 degrees, 2 x 2 image at d = 2: pixel (0, 0) is the upper-left quarter's centre,
  // at screen (-1/2, +1/2) of the half sizes hh = hw = 2 tan(45) = 2: P1 - P0 = (-1, 1, -2).
  const Json p = run("perspective", 90, 0, 0, 2, 2);
  CHECK(std::fabs(p["d"][0].get<double>() + 1) < 1e-14);
  CHECK(std::fabs(p["d"][1].get<double>() - 1) < 1e-14);
  CHECK(std::fabs(p["d"][2].get<double>() + 2) < 1e-14);
  // Fisheye: a corner of a square image lies outside the image circle.
  CHECK_FALSE(run("fisheye", 180, 0, 0, 8, 8)["valid"].get<bool>());
  CHECK(run("fisheye", 180, 4, 4, 8, 8)["valid"].get<bool>());
  // Float stays within a few float ulps of the 300-bit reference on the bench sets.
  for (const BenchRow& row : cam.bench(std::array{Numeric::f32}, {.repeats = 1, .only_set = "", .max_cases = 0, .progress = {}})) CHECK(row.max_error < 64);
  // Bad input: exact mode, pixel outside, vup parallel to vpn, unknown projection.
  CHECK_THROWS_AS(parse_numeric_for(cam, "exact"), InputError);
  Json bad = Json::parse(R"({"camera":{"eye":[1,2,3],"vpn":[0,0,2],"vup":[0,0,1],"d":2,"fov":90},"pixel":[0,0],"size":[1,1],"projection":"perspective"})");
  CHECK_THROWS_AS((void)cam.open(bad, Numeric::f64), InputError);
  bad["camera"]["vup"] = {0, 1, 0};
  bad["pixel"] = {1, 0};
  CHECK_THROWS_AS((void)cam.open(bad, Numeric::f64), InputError);
  bad["pixel"] = {0, 0};
  bad["projection"] = "orthographic";
  CHECK_THROWS_AS((void)cam.open(bad, Numeric::f64), InputError);
}

TEST_CASE("rays: sphere inverse mapping, the seam and the poles", "[rays]") {
  const Algorithm& uv = find_algorithm("sphere-uv");
  auto run = [&](double x, double y, double z) {
    return uv.open(Json{{"sphere", {{"c", {0, 0, 0}}, {"r", 1}}}, {"point", {x, y, z}}}, Numeric::f64).run();
  };
  const double pi = 3.14159265358979323846;
  const Json seam = run(-0.6, 0, 0.8);  // on the seam: atan2(+0, -0.6) = +pi, so u = 1
  CHECK(seam["lon"].get<double>() == pi);
  CHECK(seam["u"].get<double>() == 1.0);
  CHECK(run(-0.6, -1e-300, 0.8)["u"].get<double>() < 1e-15);  // just below the seam: u near 0
  const Json north = run(0, 0, 3);  // pole: lon = atan2(0, 0) = 0, u = 1/2, v = 1
  CHECK(north["u"].get<double>() == 0.5);
  CHECK(north["v"].get<double>() == 1.0);
  CHECK(north["lat"].get<double>() == pi / 2);
  const Json east = run(0, 2, 0);
  CHECK(std::fabs(east["u"].get<double>() - 0.75) < 1e-15);
  CHECK(east["v"].get<double>() == 0.5);
  CHECK(east["normal"] == Json::array({0.0, 1.0, 0.0}));
  CHECK_THROWS_AS((void)uv.open(Json::parse(R"({"sphere":{"c":[1,1,1],"r":1},"point":[1,1,1]})"), Numeric::f64), InputError);
  for (const BenchRow& row : uv.bench(std::array{Numeric::f64}, {.repeats = 1, .only_set = "", .max_cases = 0, .progress = {}})) CHECK(row.max_error < 16);
}
