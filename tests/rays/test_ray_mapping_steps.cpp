// camera-ray and sphere-uv, step by step in reference mode: every variable and geometry item a
// step records, against the closed forms of docs/rays/semantics.md evaluated here in 640-bit MPFR
// from the exact input (pi from mpfr_const_pi, not the algorithms' functions). A value is
// required exactly where the reference's is exact by construction: rational steps (the pixel
// centre, frames of Pythagorean vectors), exact roots, and the documented special values (u = 1
// on the seam, u = 1/2 and v = 0 or 1 at the poles; the axes, where MPFR's correctly rounded
// multiples of pi cancel); within 2^-200 of it elsewhere.
#include <catch2/catch.hpp>
#include "catalog.hpp"
#include "ray_steps.hpp"

using namespace sw;
using namespace sw::testing::rays;
using sw::testing::ratio;
using K = StepKind;

namespace {

VV scaled(const VV& a, const Val& s) { return {a.x * s, a.y * s, a.z * s}; }
VV operator/(const VV& a, const Val& s) { return {a.x / s, a.y / s, a.z / s}; }
// A value the reference computes from a rounded one is exact only where it is an exact zero.
VV rounded_if(const VV& a, bool rounded) {
  VV out = a;
  for (Val* c : {&out.x, &out.y, &out.z})
    if (rounded && !c->exact_zero()) c->approx = true;
  return out;
}

// camera-ray: n = VPN/|VPN|, u = (VUP x VPN)/|VUP x VPN|, v = n x u = VPN x (VUP x VPN) / (|VPN|
// |VUP x VPN|); the pixel centre (sx, sy); then the projection's direction. Returns whether a ray
// comes out.
bool camera_expected(const Json& in, Expected& e) {
  using L = ray::CameraRayAlgo;
  const Json& cj = in["camera"];
  const V3 eye = parse_point3(cj, "eye"), vpn = parse_point3(cj, "vpn"), vup = parse_point3(cj, "vup");
  const Val d(q(cj["d"])), fov = Val(cj.contains("fov") ? q(cj["fov"]) : Q(60)) * pi_val() / Val(180);
  const Q w = in["size"][0].get<int>(), h = in["size"][1].get<int>();
  const std::int64_t i = in["pixel"][0].get<std::int64_t>(), j = in["pixel"][1].get<std::int64_t>();
  const V3 side = crossq(vup, vpn);
  const Val len_n = sqrt_val(dotq(vpn, vpn)), len_u = sqrt_val(dotq(side, side));
  // The reference normalises VUP x n with n already rounded: u and v are exact only if n is.
  const VV n = lift(vpn) / len_n, u = rounded_if(lift(side) / len_u, len_n.approx);
  const VV v = rounded_if(lift(crossq(vpn, side)) / (len_n * len_u), len_n.approx);
  const VV e0 = lift(eye);
  e.step(L::frame, K::init)
      .vec("ux", "uy", "uz", u)
      .vec("vx", "vy", "vz", v)
      .vec("nx", "ny", "nz", n)
      .point(e0)
      .label("eye")
      .keep()
      .segment(e0, e0 + u)
      .label("u")
      .keep()
      .segment(e0, e0 + v)
      .label("v")
      .keep()
      .segment(e0, e0 + n)
      .label("n")
      .keep();
  const Q sx = 2 * (Q(i) + ratio(1, 2)) / w - 1, sy = 1 - 2 * (Q(j) + ratio(1, 2)) / h;
  e.step(L::screen, K::init).flag("i", i).flag("j", j).var("sx", sx).var("sy", sy);
  const Val half_fov = fov / Val(2);
  VV dir;
  const std::string proj = in["projection"];
  if (cj.contains("window")) {  // the window's point (umin + (sx+1)/2 (umax-umin), vmin + (sy+1)/2 (vmax-vmin))
    const Json& wj = cj["window"];
    const Q wu = q(wj[0]) + (sx + 1) / 2 * (q(wj[1]) - q(wj[0])), wv = q(wj[2]) + (sy + 1) / 2 * (q(wj[3]) - q(wj[2]));
    dir = scaled(n, -d) + scaled(u, Val(wu)) + scaled(v, Val(wv));
    e.step(L::given, K::advance).var("wu", wu).var("wv", wv).point(e0 + dir).label("P1").keep();
  } else if (proj == "perspective") {
    const Val hh = d * tan_val(half_fov), hw = hh * Val(Q(w / h));
    e.step(L::window, K::init).var("hh", hh).var("hw", hw);
    dir = scaled(n, -d) + scaled(u, Val(sx) * hw) + scaled(v, Val(sy) * hh);
    e.step(L::point, K::advance).point(e0 + dir).label("P1").keep();
  } else if (proj == "fisheye") {
    const Q x = sx * w / h, rho2 = x * x + sy * sy;
    const Val rho = sqrt_val(rho2), theta = rho * half_fov, phi = atan2_val(Val(sy), Val(x));
    e.step(L::fisheye, K::decide).var("rho", rho).var("theta", theta).var("phi", phi);
    if (rho2 > 1) {  // outside the image circle
      e.step(L::circle, K::miss);
      return false;
    }
    dir = scaled(scaled(u, cos_val(phi)) + scaled(v, sin_val(phi)), sin_val(theta)) - scaled(n, cos_val(theta));
  } else {
    const Val phi = Val(sx) * half_fov * Val(Q(w / h));
    e.step(L::cyl, K::decide).var("phi", phi);
    dir = scaled(scaled(u, sin_val(phi)) - scaled(n, cos_val(phi)), d) + scaled(v, Val(sy) * d * tan_val(half_fov));
  }
  e.step(L::ray, K::done).vec("dx", "dy", "dz", dir).item2(GeoKind::ray3, e0, dir).label("ray").keep();
  return true;
}

// sphere-uv, with q = P - c: N = q/|q|; lon = atan2(q_y, q_x) (0 at the poles); lat =
// atan2(q_z, sqrt(q_x^2 + q_y^2)); u = (lon + pi)/2pi, v = (lat + pi/2)/pi. The recorded sphere is
// the one through P (radius |q|).
void uv_expected(const Json& in, Expected& e) {
  using L = ray::SphereUVAlgo;
  const V3 c = parse_point3(in["sphere"], "c"), p = parse_point3(in, "point"), qv = sub(p, c);
  const Val len = sqrt_val(dotq(qv, qv));
  const VV nrm = lift(qv) / len, pp = lift(p);
  e.step(L::normal, K::init)
      .vec("Nx", "Ny", "Nz", nrm)
      .item(GeoKind::sphere, {c.x, c.y, c.z, len})
      .keep()
      .point(pp)
      .label("P")
      .keep()
      .segment(pp, pp + nrm)
      .label("N")
      .keep();
  const Val lon = atan2_val(Val(qv.y), Val(qv.x)), lat = atan2_val(Val(qv.z), sqrt_val(Q(qv.x * qv.x + qv.y * qv.y)));
  e.step(L::lon, K::advance).var("lon", lon);
  e.step(L::lat, K::advance).var("lat", lat);
  const Val pi = pi_val();
  Val u = (lon + pi) / (Val(2) * pi), v = (lat + pi / Val(2)) / pi;
  // lon = 0 on the +x half-plane and at the poles, pi on the seam, +-pi/2 on the y axis; lat = 0
  // on the equator, +-pi/2 at the poles.
  if (sgn(qv.y) == 0) u = sgn(qv.x) < 0 ? Val(1) : Val(Q(ratio(1, 2)));
  else if (sgn(qv.x) == 0) u = sgn(qv.y) > 0 ? Val(Q(ratio(3, 4))) : Val(Q(ratio(1, 4)));
  if (sgn(qv.x) == 0 && sgn(qv.y) == 0) v = sgn(qv.z) > 0 ? Val(1) : Val(0);
  else if (sgn(qv.z) == 0) v = Val(Q(ratio(1, 2)));
  e.step(L::uv, K::done).var("u", u).var("v", v);
}

// Seeded cameras: Pythagorean view-plane normals (exact frames) and arbitrary ones, every
// projection, pixels anywhere (image-circle corners included).
std::vector<Case> camera_cases(int count, std::uint64_t seed) {
  SmallRng g(seed);
  static const int pyth[][3] = {{0, 0, 1}, {0, 0, 2}, {3, 4, 0}, {1, 2, 2}, {2, 3, 6}, {0, 3, 4}, {1, 4, 8}, {2, 6, 9}};
  static const char* projections[] = {"perspective", "fisheye", "cylindrical"};
  std::vector<Case> out;
  for (int k = 0; k < count; ++k) {
    V3 vpn, vup;
    if (g.one_in(2)) {
      const auto& t = pyth[g.pick(0, 7)];
      const int r = g.pick(0, 2);
      for (int a = 0; a < 3; ++a) vpn[a] = (g.one_in(2) ? -1 : 1) * t[(a + r) % 3];
    } else {
      vpn = parse_point3(Json{{"v", g.nonzero_vec(-2, 2, false)}}, "v");
    }
    do {
      vup = g.one_in(2) ? kAxis[g.pick(0, 2)] : parse_point3(Json{{"v", g.nonzero_vec(-2, 2, false)}}, "v");
    } while (crossq(vup, vpn) == V3{});
    const int proj = g.pick(0, 2), w = g.pick(1, 9), h = g.pick(1, 9);
    const Json fov = g.one_in(6) ? Json("45/2") : Json(proj == 1 ? g.pick(1, 360) : g.pick(1, 179));
    auto js = [](const V3& x) { return Json::array({x.x.get_str(), x.y.get_str(), x.z.get_str()}); };
    Json cam = {{"eye", g.vec(-3, 3)},
                {"vpn", js(vpn)},
                {"vup", js(vup)},
                {"d", std::array{"1", "2", "1/2", "3/2"}[g.pick(0, 3)]},
                {"fov", fov}};
    if (proj == 0 && g.one_in(3)) {  // the notes' window, possibly off-centre
      const int u0 = g.pick(-3, 1), v0 = g.pick(-3, 1);
      cam.erase("fov");
      cam["window"] = {u0, u0 + g.pick(1, 4), std::to_string(v0) + "/2", std::to_string(v0 + 2 * g.pick(1, 3)) + "/2"};
    }
    out.push_back({"small " + std::to_string(k),
                   {{"camera", cam},
                    {"pixel", {g.pick(0, w - 1), g.pick(0, h - 1)}},
                    {"size", {w, h}},
                    {"projection", projections[proj]}}});
  }
  return out;
}

// Seeded points: zero components often, so the poles, the seam and the axes come up.
std::vector<Case> uv_cases(int count, std::uint64_t seed) {
  SmallRng g(seed);
  std::vector<Case> out;
  for (int k = 0; k < count; ++k) {
    const Json c = g.vec(-2, 2);
    Json p = Json::array();
    do {
      p = Json::array();
      for (int a = 0; a < 3; ++a) p.push_back(g.one_in(3) ? c[a] : Json(Q(q(c[a]) + q(g.num(-3, 3))).get_str()));
    } while (p == c);
    out.push_back({"small " + std::to_string(k), {{"sphere", {{"c", c}, {"r", g.pick(1, 2)}}}, {"point", p}}});
  }
  return out;
}

}  // namespace

TEST_CASE("rays: camera-ray, every reference step value and geometry item matches its closed form", "[rays][steps][replay]") {
  std::vector<Case> cases = example_and_lessons("camera-ray");
  for (Case& c : corpus_cases("camera")) cases.push_back(std::move(c));
  for (Case& c : camera_cases(300, 501)) cases.push_back(std::move(c));
  std::set<std::string_view> seen;
  int exact_frames = 0, rounded_frames = 0, outside_circle = 0, centre = 0;
  for (const Case& c : cases) {
    INFO("camera-ray, " << c.name << ": " << c.input.dump());
    (void)find_algorithm("camera-ray").open(c.input, Numeric::reference);
    Recorder<Q> t;
    const bool valid = record_direct("camera-ray", c.input, t).hit;
    Expected want;
    CHECK(valid == camera_expected(c.input, want));
    require_matches(t, ray::CameraRayAlgo::listing(), want, seen);
    const V3 vpn = parse_point3(c.input["camera"], "vpn"), side = crossq(parse_point3(c.input["camera"], "vup"), vpn);
    const bool exact = !sqrt_val(dotq(vpn, vpn)).approx && !sqrt_val(dotq(side, side)).approx;
    exact_frames += exact, rounded_frames += !exact;
    outside_circle += !valid;
    centre += want.steps[1].vars[2].second.v == 0 && want.steps[1].vars[3].second.v == 0;
  }
  CHECK(seen == recorded_lines(ray::CameraRayAlgo::listing(), {}));
  CHECK(exact_frames > 0);
  CHECK(rounded_frames > 0);
  CHECK(outside_circle > 0);
  CHECK(centre > 0);
}

TEST_CASE("rays: sphere inverse mapping, every reference step value and geometry item matches its closed form",
          "[rays][steps][replay]") {
  std::vector<Case> cases = example_and_lessons("sphere-uv");
  for (Case& c : corpus_cases("point")) cases.push_back(std::move(c));
  for (Case& c : uv_cases(300, 502)) cases.push_back(std::move(c));
  std::set<std::string_view> seen;
  int poles = 0, seam = 0, y_axis = 0, rounded = 0, exact_normal = 0;
  for (const Case& c : cases) {
    INFO("sphere-uv, " << c.name << ": " << c.input.dump());
    (void)find_algorithm("sphere-uv").open(c.input, Numeric::reference);
    Recorder<Q> t;
    record_direct("sphere-uv", c.input, t);
    Expected want;
    uv_expected(c.input, want);
    require_matches(t, ray::SphereUVAlgo::listing(), want, seen);
    const V3 qv = sub(parse_point3(c.input, "point"), parse_point3(c.input["sphere"], "c"));
    poles += sgn(qv.x) == 0 && sgn(qv.y) == 0;
    seam += sgn(qv.y) == 0 && sgn(qv.x) < 0;
    y_axis += sgn(qv.x) == 0 && sgn(qv.y) != 0;
    rounded += want.steps[3].vars[0].second.approx;
    exact_normal += !sqrt_val(dotq(qv, qv)).approx;
  }
  CHECK(seen == recorded_lines(ray::SphereUVAlgo::listing(), {}));
  CHECK(poles > 0);
  CHECK(seam > 0);
  CHECK(y_axis > 0);
  CHECK(rounded > 0);
  CHECK(exact_normal > 0);
}
