// The curves family's cubic Bezier: bezier-forward-diff's and bezier-de-casteljau's catalog entries
// (registered here).
// Semantics: docs/curves/semantics.md.
#include <bit>
#include <random>
#include "register.hpp"
#include "curves/bezier_de_casteljau.hpp"
#include "curves/bezier_forward_diff.hpp"
#include "curves/outlines.hpp"
#include "curves_bezier_oracle.hpp"
#include "pixels.hpp"

namespace sw {
namespace {

struct BezierInput {
  std::array<Vec2<Rational>, 4> p;
  std::int64_t n = 1;
};

struct BezierSpec {
  static constexpr std::array hooks{Hook::table_lines, Hook::outline, Hook::handles, Hook::write_members, Hook::estimate_steps};
  using Algo = curves::BezierForwardDiff;
  using Input = BezierInput;
  using Output = PixelsOutput;
  static constexpr std::int64_t kMaxCoord = std::int64_t{1} << 16, kMaxSegments = 1024;
  static constexpr std::array views{View::plane2d, View::table};
  static constexpr std::array<std::string_view, 1> table_lines{"step"};  // one row per segment
  static std::vector<Polyline2> outline(const Input& in, const Rect2&, double cell) { return curves::bezier_outline(in.p, cell); }
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example = R"({"bezier":[[0.5,0],[3,"29/4"],[9.5,"-5/3"],[12,6]],"n":6})";
  // The control points, and the number of pieces under `key` (n itself, or a depth: n = 2^depth).
  static Input parse_pieces(const Json& j, const char* key, std::int64_t max, bool depth) {
    only_keys(j, {"bezier", key}, "input");
    const Json& b = j["bezier"];
    if (!b.is_array() || b.size() != 4) throw InputError("input.bezier: expected four control points [[x,y],[x,y],[x,y],[x,y]]");
    Input in;
    for (int i = 0; i < 4; ++i) {
      const std::string what = "input.bezier[" + std::to_string(i) + "]";
      if (!b[i].is_array() || b[i].size() != 2) throw InputError(what + ": expected [x, y]");
      for (int a = 0; a < 2; ++a) {
        in.p[i][a] = parse_rational(b[i][a], what + "[" + std::to_string(a) + "]");
        check_bound(in.p[i][a], double(kMaxCoord), what + "[" + std::to_string(a) + "]");
        check_digits(in.p[i][a], what + "[" + std::to_string(a) + "]");
      }
    }
    const std::int64_t v = parse_integer(j[key], std::string("input.") + key, depth ? 0 : 1, max);
    in.n = depth ? std::int64_t{1} << v : v;
    return in;
  }
  static Input parse(const Json& j) { return parse_pieces(j, "n", kMaxSegments, false); }
  static std::vector<Handle> handles() {
    std::vector<Handle> h;
    for (int i = 0; i < 4; ++i) h.push_back({"/bezier/" + std::to_string(i), Handle::Kind::point2, 8, "P" + std::to_string(i)});
    return h;
  }
  template <class Num> static curves::Bezier<Num> prepare(const Input& in) {
    curves::Bezier<Num> b;
    for (int i = 0; i < 4; ++i) b.p[i] = to_num<Num>(in.p[i]);
    b.n = in.n;
    return b;
  }
  template <class Num, class Probe> static Output compute(const curves::Bezier<Num>& b, Probe& probe) {
    Output o;
    curves::bezier_forward_diff<Num>(b, o.pixels, probe);
    return o;
  }
  static Json to_json(const Output& o) { return pixels_json("pixels", o); }
  static void write_members(const Output& o, std::ostream& os) { pixels_members("pixels", o, os); }
  static std::size_t ops(const Output& o) { return o.pixels.size(); }
  // The curve lies in the control points' hull: at most its box's width + height pixels per pass.
  static std::size_t estimate_steps(const Input& in) {
    Rational span = 0;
    for (int i = 0; i < 3; ++i) span += abs(Rational(in.p[i + 1].x - in.p[i].x)) + abs(Rational(in.p[i + 1].y - in.p[i].y));
    return 3 * static_cast<std::size_t>(num::ceil_int(span)) + 8 * static_cast<std::size_t>(in.n) + 16;
  }
  static Output oracle(const Input& in) { return {oracle::bezier_pixels(in.p, in.n)}; }
  static std::vector<BenchSet<Input>> bench_sets() { return bench_sets_for(false); }
  // Random curves of 4 to 32 pieces (powers of two for a depth), and curves of 1024 pieces.
  static std::vector<BenchSet<Input>> bench_sets_for(bool powers_of_two) {
    std::mt19937_64 rng(20261125);
    auto u = [&](long lo, long hi) {
      Rational r(std::uniform_int_distribution<long>(lo, hi)(rng), 8);
      r.canonicalize();
      return r;
    };
    BenchSet<Input> random{"random", {}}, fine{"fine", {}};
    for (int i = 0; i < 1000; ++i) {
      Input in;
      for (auto& c : in.p) c = {u(-2000, 2000), u(-2000, 2000)};
      in.n = powers_of_two ? std::int64_t{1} << std::uniform_int_distribution<int>(2, 5)(rng) : std::uniform_int_distribution<std::int64_t>(4, 32)(rng);
      random.inputs.push_back(in);
    }
    // Many short pieces: the forward-difference table runs long, the DDA segments are short.
    for (int i = 0; i < 20; ++i) {
      Input in;
      for (auto& c : in.p) c = {u(-8000, 8000), u(-8000, 8000)};
      in.n = 1024;
      fine.inputs.push_back(in);
    }
    return {random, fine};
  }
};

// The same curves cut by de Casteljau halving: input {"bezier": [...], "depth": d}, n = 2^d pieces.
struct BezierDeCasteljauSpec : BezierSpec {
  using Algo = curves::BezierDeCasteljau;
  static constexpr std::int64_t kMaxDepth = 10;  // 1024 pieces, as bezier-forward-diff's bound
  static constexpr std::array<std::string_view, 1> table_lines{"leaf"};  // one row per chord
  static inline const std::string example = R"({"bezier":[[0.5,0],[3,"29/4"],[9.5,"-5/3"],[12,6]],"depth":3})";
  static Input parse(const Json& j) { return parse_pieces(j, "depth", kMaxDepth, true); }
  template <class Num> static curves::BezierDepth<Num> prepare(const Input& in) {
    curves::BezierDepth<Num> b;
    for (int i = 0; i < 4; ++i) b.p[i] = to_num<Num>(in.p[i]);
    b.depth = std::countr_zero(static_cast<std::uint64_t>(in.n));
    return b;
  }
  template <class Num, class Probe> static Output compute(const curves::BezierDepth<Num>& b, Probe& probe) {
    Output o;
    curves::bezier_de_casteljau<Num>(b, o.pixels, probe);
    return o;
  }
  static std::vector<BenchSet<Input>> bench_sets() { return bench_sets_for(true); }
};

SW_REGISTER(BezierSpec);
SW_REGISTER(BezierDeCasteljauSpec);

}  // namespace

}  // namespace sw
