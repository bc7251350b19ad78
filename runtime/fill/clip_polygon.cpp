// sutherland-hodgman in the catalog (registered here).
// Semantics, bounds and the region comparison: docs/fill/clipping.md.
#include <numbers>
#include "fill/sutherland_hodgman.hpp"
#include "fill/clip_common.hpp"

namespace sw {
namespace {

using namespace clipspec;
using oracle::Polygon2;

struct PolygonClipInput {
  Polygon2 subject, clip;
};

struct PolygonClipOutput : PolygonPoints {
  // Exact results compared as regions (winding numbers), not vertex lists.
  friend bool operator==(const PolygonClipOutput& a, const PolygonClipOutput& b) {
    if (a.exact && b.exact) return oracle::same_region(*a.exact, *b.exact);
    return clip_equal<PolygonPoints>(a, b, [](const Polygon2&, const Polygon2&) { return true; });
  }
};

template <class Num> struct PreparedPolygons {
  std::vector<Vec2<Num>> subject, clip;
};

Polygon2 window_polygon(const Vec2<Rational>& lo, const Vec2<Rational>& hi) { return {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}; }

struct SutherlandHodgmanSpec {
  static constexpr std::array hooks{Hook::handles, Hook::estimate_steps, Hook::canonical, Hook::error, Hook::table_lines};
  using Algo = fill::SutherlandHodgman;
  using Input = PolygonClipInput;
  using Output = PolygonClipOutput;
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array<std::string_view, 1> table_lines{"side"};  // one row per vertex decision
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"polygon":[[0,0],[10,0],[10,8],[5,3],[0,8]],"clip":[[2,-2],[12,2],[9,9],[1,7],[-1,2]]})";

  static Input parse(const Json& j) {
    if (!j.is_object()) throw InputError("input: expected an object");
    Input in;
    if (j.contains("window")) {
      only_keys(j, {"polygon", "window"}, "input");
      const auto w = parse_window(j["window"], true);
      in.clip = window_polygon(w[0], w[1]);
    } else {
      only_keys(j, {"polygon", "clip"}, "input");
      in.clip = parse_polygon(j["clip"], "input.clip", kMaxClip);
      check_convex(in.clip, "input.clip");
    }
    in.subject = parse_polygon(j["polygon"], "input.polygon", kMaxSubject);
    return in;
  }
  template <class Num> static PreparedPolygons<Num> prepare(const Input& in) {
    PreparedPolygons<Num> p;
    for (const auto& v : in.subject) p.subject.push_back(to_num<Num>(v));
    for (const auto& v : in.clip) p.clip.push_back(to_num<Num>(v));
    return p;
  }
  template <class Num, class Probe> static Output compute(const PreparedPolygons<Num>& p, Probe& probe) {
    Output o;
    set_points<Num>(o, fill::sutherland_hodgman<Num>(p.subject, p.clip, probe));
    return o;
  }
  static Json to_json(const Output& o) { return {{"polygon", points_json(o)}}; }
  static std::size_t ops(const Output&) { return 1; }  // ns per clipped polygon
  // Per clip edge: its own step and up to three per vertex of a polygon that can at most double.
  static std::size_t estimate_steps(const Input& in) { return in.clip.size() * (2 + 6 * in.subject.size()) + 4; }
  static Output oracle(const Input& in) {
    Output o;
    set_points<Rational>(o, oracle::clip_polygon(in.subject, in.clip));
    return o;
  }
  // The region: the polygon's reduced boundary chain, [x0, y0, x1, y1, weight] per piece.
  static Json canonical(Json result) {
    Json chain = Json::array();
    for (const oracle::BoundaryPiece& p : oracle::boundary_chain(points_of(result["polygon"], "result.polygon")))
      chain.push_back({p.a.x.get_str(), p.a.y.get_str(), p.b.x.get_str(), p.b.y.get_str(), p.weight});
    return {{"boundary", chain}};
  }
  static constexpr std::string_view error_unit = "ulps";
  static double error(const Output& got, const Output& exact) {
    if (!exact.exact || got.exact || got.lo.size() != exact.exact->size()) return 0;
    return ulps_error(got, *exact.exact);
  }
  static std::vector<Handle> handles() {
    std::vector<Handle> h;  // the example's vertices
    for (int i = 0; i < 5; ++i) h.push_back({"/polygon/" + std::to_string(i), Handle::Kind::point2, 8, "v" + std::to_string(i)});
    for (int i = 0; i < 5; ++i) h.push_back({"/clip/" + std::to_string(i), Handle::Kind::point2, 8, "c" + std::to_string(i)});
    return h;
  }
  static std::vector<BenchSet<Input>> bench_sets();
};

// A star-shaped polygon of n vertices around c (random angles and radii): often concave.
Polygon2 random_star(ClipRng& g, const Vec2<Rational>& c, double r, int n) {
  std::vector<double> angles;
  for (int i = 0; i < n; ++i) angles.push_back(std::uniform_real_distribution<double>(0, 2 * std::numbers::pi)(g.rng));
  std::sort(angles.begin(), angles.end());
  Polygon2 p;
  for (double a : angles) {
    const double rr = r * std::uniform_real_distribution<double>(0.2, 1.0)(g.rng);
    p.push_back({c.x + num::to_rational(std::ldexp(std::round(std::ldexp(rr * std::cos(a), 20)), -20)),
                 c.y + num::to_rational(std::ldexp(std::round(std::ldexp(rr * std::sin(a), 20)), -20))});
  }
  return p;
}

// A convex polygon of n vertices on a circle (angles at least 2 pi / 4n apart), either orientation.
Polygon2 random_convex(ClipRng& g, const Vec2<Rational>& c, double r, int n) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    Polygon2 p;
    const double start = std::uniform_real_distribution<double>(0, 2 * std::numbers::pi)(g.rng);
    for (int i = 0; i < n; ++i) {
      const double a = start + 2 * std::numbers::pi * (i + std::uniform_real_distribution<double>(0, 0.75)(g.rng)) / n;
      p.push_back({c.x + num::to_rational(std::ldexp(std::round(std::ldexp(r * std::cos(a), 20)), -20)),
                   c.y + num::to_rational(std::ldexp(std::round(std::ldexp(r * std::sin(a), 20)), -20))});
    }
    if (g.pick(0, 1)) std::reverse(p.begin(), p.end());
    try {
      check_convex(p, "bench");
      return p;
    } catch (const InputError&) {
    }
  }
  return window_polygon(c - Vec2<Rational>{1, 1}, c + Vec2<Rational>{1, 1});
}

// random: star-shaped subjects of 3 to 16 vertices against convex polygons of 3 to 8 and windows.
// hard: the subject equal to the window, combs whose teeth leave bridges, collinear and repeated
// vertices on the clip lines, clockwise clip polygons, coordinates near 2^30.
std::vector<BenchSet<PolygonClipInput>> SutherlandHodgmanSpec::bench_sets() {
  ClipRng g{std::mt19937_64(20261131)};
  BenchSet<Input> random{"random", {}}, hard{"hard", {}};
  for (int i = 0; i < 2000; ++i) {
    Input in;
    in.subject = random_star(g, g.point(-64, 64), 200, g.pick(3, 16));
    if (i % 4 == 0) {
      const Vec2<Rational> lo = g.point(-200, 0);
      in.clip = window_polygon(lo, lo + g.point(50, 250));
    } else {
      in.clip = random_convex(g, g.point(-64, 64), g.coord(60, 220).get_d(), g.pick(3, 8));
    }
    random.inputs.push_back(std::move(in));
  }
  for (int i = 0; i < 500; ++i) {
    const double s = i % 2 ? 1 : 1048576;  // unit scale and 2^20 (coordinates up to 2^30)
    auto at = [&](double x, double y) { return Vec2<Rational>{num::to_rational(x * s), num::to_rational(y * s)}; };
    Input in;
    in.clip = window_polygon(at(0, 0), at(512, 256));
    switch (i % 5) {
      case 0: in.subject = in.clip; break;  // the window itself
      case 1: {  // a comb with teeth up through y = 256: bridges along the top edge
        const int teeth = g.pick(2, 6);
        in.subject = {at(-8, 8)};
        for (int k = 0; k < teeth; ++k) {
          const double x0 = 8 + 480.0 * k / teeth, x1 = x0 + 240.0 / teeth;
          for (const auto& v : {at(x0, 300), at(x0 + 0.5, 300), at(x1, 300), at(x1, 100)}) in.subject.push_back(v);
        }
        in.subject.push_back(at(520, 40));
        break;
      }
      case 2:  // collinear and repeated vertices, some on the window's edge lines
        in.subject = {at(-100, 0), at(0, 0), at(0, 0), at(200, 0), at(600, 0), at(600, 128), at(256, 256), at(256, 256), at(-100, 256)};
        break;
      case 3:  // the window clockwise, a random subject
        std::reverse(in.clip.begin(), in.clip.end());
        in.subject = random_star(g, at(256, 128), 400 * s, g.pick(3, 16));
        break;
      default:  // vertices within 2^-40 (relative) of the window's edge lines
        in.subject = {at(-10, std::ldexp(g.pick(-3, 3), -40)), at(600, std::ldexp(g.pick(-3, 3), -40)), at(512 + std::ldexp(g.pick(-3, 3), -30), 300),
                      at(256, 256 + std::ldexp(g.pick(-3, 3), -32))};
        break;
    }
    hard.inputs.push_back(std::move(in));
  }
  for (auto* set : {&random, &hard})
    std::erase_if(set->inputs, [](const Input& in) {
      for (const auto& p : in.subject)
        if (abs(p.x) > Rational(fillspec::kCoordBound) || abs(p.y) > Rational(fillspec::kCoordBound)) return true;
      return false;
    });
  return {random, hard};
}

SW_REGISTER(SutherlandHodgmanSpec);

}  // namespace

}  // namespace sw
