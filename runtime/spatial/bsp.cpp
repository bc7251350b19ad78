// bsp-build and bsp-painter in the catalog: input {"segments":[[[x0,y0],[x1,y1]],...]} (plus
// "eye":[x,y] for the painter), the fragment budget, and the results. Semantics: docs/spatial/bsp.md.
#include <cmath>
#include <memory>
#include <random>
#include "register.hpp"
#include "spatial/bsp_painter.hpp"
#include "spatial/spatial_common.hpp"

namespace sw {
namespace {

using namespace spatial;

constexpr std::size_t kMaxSegments = 4096;
constexpr std::size_t kMaxFragments = std::size_t{1} << 17;  // the largest accepted exact trace within 10 s

struct BspData {
  std::vector<std::array<double, 4>> segs;  // x0 y0 x1 y1
  std::array<double, 2> eye{};
};
struct BspInput {
  std::shared_ptr<const BspData> d;
};

// An upper bound on the exact build's fragments: n plus the pairs (i, j) whose line i may cross
// segment j, since each such pair cuts at most once (docs/spatial/bsp.md). A pair counts unless
// orient2d in double, within Shewchuk's error bound, puts both ends of j strictly on one side.
std::size_t fragment_bound(const BspData& in, std::size_t stop) {
  const std::size_t n = in.segs.size();
  std::size_t count = n;
  for (std::size_t i = 0; i < n && count <= stop; ++i) {
    const auto& l = in.segs[i];
    const double dx = l[2] - l[0], dy = l[3] - l[1];
    auto side = [&](double x, double y) {
      const double u = dx * (y - l[1]), v = dy * (x - l[0]), det = u - v, mag = std::fabs(u) + std::fabs(v);
      if (mag < 1e-250) return 0;  // products near underflow: no relative bound, count the pair
      const double err = 4e-16 * mag;
      return det > err ? 1 : det < -err ? -1 : 0;
    };
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const int sa = side(in.segs[j][0], in.segs[j][1]), sb = side(in.segs[j][2], in.segs[j][3]);
      if (sa == 0 || sa != sb) ++count;
    }
  }
  return count;
}

BspInput parse_bsp(const Json& j, bool with_eye) {
  if (with_eye) only_keys(j, {"segments", "eye"}, "input");
  else only_keys(j, {"segments"}, "input");
  const Json& s = j["segments"];
  if (!s.is_array() || s.empty()) throw InputError("input.segments: expected a non-empty array of segments [[[x0,y0],[x1,y1]],...]");
  if (s.size() > kMaxSegments)
    throw InputError("input.segments: " + std::to_string(s.size()) + " segments, more than the bound " + std::to_string(kMaxSegments));
  auto d = std::make_shared<BspData>();
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::string w = "input.segments[" + std::to_string(i) + "]";
    if (!s[i].is_array() || s[i].size() != 2) throw InputError(w + ": expected [[x0,y0],[x1,y1]]");
    const auto a = parse_vec<2>(s[i][0], w + "[0]"), b = parse_vec<2>(s[i][1], w + "[1]");
    if (a == b) throw InputError(w + ": zero length (both ends are " + Json(a).dump() + ")");
    d->segs.push_back({a[0], a[1], b[0], b[1]});
  }
  if (with_eye) d->eye = parse_vec<2>(j["eye"], "input.eye");
  const std::size_t bound = fragment_bound(*d, kMaxFragments);
  if (bound > kMaxFragments)
    throw InputError("input.segments: up to " + std::to_string(bound) + "+ fragments (segments plus line-segment crossings), more than the budget " +
                     std::to_string(kMaxFragments));
  return {std::move(d)};
}

template <class Num> struct Prepared {
  std::vector<Segment2<Num>> segs;
  Vec2<Num> eye;
  std::shared_ptr<const BspData> d;
};
template <class Num> Prepared<Num> prepare_bsp(const BspInput& in) {
  Prepared<Num> p{{}, {from_double<Num>(in.d->eye[0]), from_double<Num>(in.d->eye[1])}, in.d};
  for (const auto& s : in.d->segs) p.segs.push_back({{from_double<Num>(s[0]), from_double<Num>(s[1])}, {from_double<Num>(s[2]), from_double<Num>(s[3])}});
  return p;
}

// One output for every mode: the tree, the fragments (the mode's values; exact mode's rationals),
// and the painter's order. Filtered mode's decisions are exact, so its fragments' exact ends are
// the crossings their cuts name, computed from the input when written.
struct BspOutput {
  int bits = 53;
  bool filtered = false;
  std::vector<BspNode> nodes;
  struct Frag {
    std::int32_t seg = -1, cut_a = -1, cut_b = -1;
    std::array<double, 4> ab{};
  };
  std::vector<Frag> frags;
  std::vector<std::array<Rational, 4>> exact;  // exact mode only
  std::vector<std::array<double, 4>> boxes;    // per node: lo x, lo y, hi x, hi y
  std::size_t depth = 0, splits = 0, leaves = 0;
  std::vector<std::int32_t> order;
  std::shared_ptr<const BspData> d;

  // The same tree, fragments (segment and cuts) and order, and when both are exact, the same ends.
  friend bool operator==(const BspOutput& x, const BspOutput& y) {
    if (x.nodes.size() != y.nodes.size() || x.frags.size() != y.frags.size() || x.order != y.order) return false;
    for (std::size_t i = 0; i < x.nodes.size(); ++i) {
      const BspNode &a = x.nodes[i], &b = y.nodes[i];
      if (a.parent != b.parent || a.splitter != b.splitter || a.front != b.front || a.back != b.back || a.frags != b.frags) return false;
    }
    for (std::size_t i = 0; i < x.frags.size(); ++i)
      if (x.frags[i].seg != y.frags[i].seg || x.frags[i].cut_a != y.frags[i].cut_a || x.frags[i].cut_b != y.frags[i].cut_b) return false;
    return x.exact.empty() || y.exact.empty() || x.exact == y.exact;
  }
};

template <class Num> BspOutput make_output(const BspTree<Num>& t, const std::shared_ptr<const BspData>& d) {
  if (t.exhausted) throw InputError("input.segments: this mode's rounded cuts passed the fragment budget " + std::to_string(kMaxFragments));
  BspOutput o;
  o.bits = std::is_same_v<Num, float> ? 24 : 53;
  o.filtered = is_filtered<Num>;
  o.nodes = t.nodes;
  o.depth = t.depth, o.splits = t.splits, o.leaves = t.leaves, o.d = d;
  for (const auto& f : t.frags) {
    o.frags.push_back({f.seg, f.cut_a, f.cut_b, {num::to_double(f.a.x), num::to_double(f.a.y), num::to_double(f.b.x), num::to_double(f.b.y)}});
    if constexpr (std::is_same_v<Num, Rational>) o.exact.push_back({f.a.x, f.a.y, f.b.x, f.b.y});
  }
  for (const auto& b : t.boxes) o.boxes.push_back({num::to_double(b.lo.x), num::to_double(b.lo.y), num::to_double(b.hi.x), num::to_double(b.hi.y)});
  return o;
}

// The crossing of segment `seg`'s line with segment `cut`'s line, or seg's own end if cut < 0.
Vec2<Rational> end_point(const BspData& d, std::int32_t seg, std::int32_t cut, bool b_end) {
  const auto& s = d.segs[static_cast<std::size_t>(seg)];
  const Vec2<Rational> p{num::to_rational(s[0]), num::to_rational(s[1])}, q{num::to_rational(s[2]), num::to_rational(s[3])};
  if (cut < 0) return b_end ? q : p;
  const auto& c = d.segs[static_cast<std::size_t>(cut)];
  const Vec2<Rational> u{num::to_rational(c[0]), num::to_rational(c[1])}, v{num::to_rational(c[2]), num::to_rational(c[3])};
  const Rational sp = orient2(u, v, p), sq = orient2(u, v, q);
  return p + Rational(sp / Rational(sp - sq)) * (q - p);
}

Json fragments_json(const BspOutput& o) {
  Json out = Json::array();
  for (std::size_t f = 0; f < o.frags.size(); ++f) {
    const auto& g = o.frags[f];
    Json a, b;
    if (!o.exact.empty()) {
      a = {o.exact[f][0].get_str(), o.exact[f][1].get_str()}, b = {o.exact[f][2].get_str(), o.exact[f][3].get_str()};
    } else if (o.filtered) {
      const Vec2<Rational> p = end_point(*o.d, g.seg, g.cut_a, false), q = end_point(*o.d, g.seg, g.cut_b, true);
      a = {p.x.get_str(), p.y.get_str()}, b = {q.x.get_str(), q.y.get_str()};
    } else {
      a = {g.ab[0], g.ab[1]}, b = {g.ab[2], g.ab[3]};
    }
    out.push_back({{"seg", g.seg}, {"a", std::move(a)}, {"b", std::move(b)}});
  }
  return out;
}

// Random segments: `crossing` long ones across a square, or one short segment inside each cell of
// a grid (no two meet). Ends on a 1/256 grid.
BspInput random_bsp(std::mt19937_64& rng, std::size_t n, bool crossing, bool eye) {
  auto d = std::make_shared<BspData>();
  std::uniform_real_distribution<double> u(0, 1);
  auto grid = [](double x) { return std::floor(x * 256) / 256; };
  const std::size_t side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
  for (std::size_t i = 0; i < n; ++i) {
    std::array<double, 4> s;
    do {
      if (crossing) {
        for (double& x : s) x = grid(-100 + 200 * u(rng));
      } else {
        const double cx = static_cast<double>(i % side) * 10, cy = static_cast<double>(i / side) * 10;
        s = {grid(cx + 1 + 8 * u(rng)), grid(cy + 1 + 8 * u(rng)), grid(cx + 1 + 8 * u(rng)), grid(cy + 1 + 8 * u(rng))};
      }
    } while (s[0] == s[2] && s[1] == s[3]);
    d->segs.push_back(s);
  }
  if (eye) d->eye = {grid(-150 + 300 * u(rng)), grid(-150 + 300 * u(rng))};
  return {std::move(d)};
}

template <bool Painter> struct BspSpec {
  static constexpr std::array hooks{Hook::handles, Hook::error};
  using Algo = std::conditional_t<Painter, BspPainter, BspBuild>;
  using Input = BspInput;
  using Output = BspOutput;
  static constexpr std::array views = Painter ? std::array{View::plane2d, View::tree} : std::array{View::tree, View::plane2d};
  static constexpr std::array numerics{Numeric::f32, Numeric::f64, Numeric::filtered, Numeric::exact};
  static inline const std::string example = std::string(R"({"segments":[[[0,0],[8,8]],[[8,0],[0,8]],[[-2,3],[10,3]],[[2,10],[6,10]],[[10,10],[12,12]],[[1,-3],[7,-3]]])") +
                                            (Painter ? R"(,"eye":[3,-6]})" : "}");
  static Input parse(const Json& j) { return parse_bsp(j, Painter); }
  static std::vector<Handle> handles() {
    std::vector<Handle> h;
    if (Painter) h.push_back({"/eye", Handle::Kind::point2, 8, "eye"});
    for (int i = 0; i < 3; ++i)
      for (int e = 0; e < 2; ++e) h.push_back({"/segments/" + std::to_string(i) + "/" + std::to_string(e), Handle::Kind::point2, 8, e ? "b" : "a"});
    return h;
  }
  template <class Num> static Prepared<Num> prepare(const Input& in) { return prepare_bsp<Num>(in); }
  template <class Num, class Probe> static Output compute(const Prepared<Num>& p, Probe& probe) {
    if constexpr (Painter) {
      const BspPaint<Num> r = bsp_painter<Num>(p.segs, p.eye, kMaxFragments, probe);
      Output o = make_output(r.tree, p.d);
      o.order = r.order;
      return o;
    } else {
      return make_output(bsp_build<Num>(p.segs, kMaxFragments, probe), p.d);
    }
  }
  static Json to_json(const Output& o) {
    if constexpr (Painter) return {{"order", o.order}, {"fragments", fragments_json(o)}};
    Json tree = Json::array();
    for (std::size_t i = 0; i < o.nodes.size(); ++i) {
      const BspNode& n = o.nodes[i];
      const auto& b = o.boxes[i];
      tree.push_back({{"parent", n.parent}, {"splitter", n.splitter}, {"front", n.front}, {"back", n.back}, {"frags", n.frags}, {"lo", {b[0], b[1]}}, {"hi", {b[2], b[3]}}});
    }
    return {{"nodes", o.nodes.size()}, {"leaves", o.leaves}, {"depth", o.depth}, {"splits", o.splits}, {"fragment_count", o.frags.size()},
            {"fragments", fragments_json(o)}, {"tree", std::move(tree)}};
  }
  static std::size_t ops(const Output& o) { return o.frags.size(); }
  // The largest error of a fragment end, in ulps of the mode at the end's larger coordinate, over
  // cases whose tree is exact's (a different tree is a mismatch); filtered ends are exact by their cuts.
  static constexpr std::string_view error_unit = "ulps";
  static double error(const Output& got, const Output& exact) {
    if (!(got == exact) || got.filtered || !got.exact.empty() || exact.exact.empty()) return 0;
    double worst = 0;
    for (std::size_t f = 0; f < got.frags.size(); ++f)
      for (int e = 0; e < 2; ++e) {
        const Rational &x = exact.exact[f][2 * e], &y = exact.exact[f][2 * e + 1];
        const double scale = std::max(std::fabs(x.get_d()), std::fabs(y.get_d()));
        if (scale == 0) continue;
        for (int k = 0; k < 2; ++k) {
          const Rational diff = abs(Rational(num::to_rational(got.frags[f].ab[2 * e + k]) - exact.exact[f][2 * e + k]));
          worst = std::max(worst, std::ldexp(diff.get_d(), got.bits - 1 - std::ilogb(scale)));
        }
      }
    return worst;
  }
  // The tree is defined by its procedure (the splitter rule, docs/spatial/bsp.md): the exact run.
  // The tests hold it to the independent statements of oracle/spatial_bsp_oracle.hpp.
  static Output oracle(const Input& in) {
    NoProbe none;
    return compute<Rational>(prepare<Rational>(in), none);
  }
  static std::vector<BenchSet<Input>> bench_sets() {
    std::mt19937_64 rng(Painter ? 20261125 : 20261124);
    BenchSet<Input> crossing{"crossing-64", {}}, disjoint{"disjoint-256", {}};
    for (int k = 0; k < 40; ++k) crossing.inputs.push_back(random_bsp(rng, 64, true, Painter));
    for (int k = 0; k < 10; ++k) disjoint.inputs.push_back(random_bsp(rng, 256, false, Painter));
    return {crossing, disjoint};
  }
};

SW_REGISTER(BspSpec<false>);
SW_REGISTER(BspSpec<true>);

}  // namespace

}  // namespace sw
