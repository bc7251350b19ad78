#include "fill_interp_oracle.hpp"
#include <algorithm>
#include <stdexcept>
#include "fill_oracle.hpp"

namespace sw::oracle {
namespace {

Rational det3(const Rational& a, const Rational& b, const Rational& c, const Rational& d, const Rational& e, const Rational& f, const Rational& g,
              const Rational& h, const Rational& i) {
  return Rational(a * Rational(e * i - f * h) - b * Rational(d * i - f * g) + c * Rational(d * h - e * g));
}

std::vector<std::vector<Vec2<Rational>>> ring_of(const std::vector<Vec2<Rational>>& pts) { return {pts}; }

}  // namespace

ClippedPolygon clip_w(const std::array<ClipPoint, 3>& v, const std::array<std::vector<Rational>, 3>& attrs, const Rational& w_near) {
  ClippedPolygon out;
  for (int k = 0; k < 3; ++k) {
    const int l = (k + 1) % 3;
    const Rational dk = v[k][3] - w_near, dl = v[l][3] - w_near;
    if (sgn(dk) >= 0) out.corners.push_back(v[k]), out.attrs.push_back(attrs[k]);
    if (sgn(dk) * sgn(dl) < 0) {  // the edge crosses the plane strictly: where w = w_near
      const Rational t = dk / Rational(dk - dl);
      ClipPoint c;
      for (int a = 0; a < 4; ++a) c[a] = v[k][a] + t * Rational(v[l][a] - v[k][a]);
      std::vector<Rational> at;
      for (std::size_t a = 0; a < attrs[k].size(); ++a) at.push_back(attrs[k][a] + t * Rational(attrs[l][a] - attrs[k][a]));
      out.corners.push_back(c), out.attrs.push_back(std::move(at));
    }
  }
  return out;
}

std::vector<Vec2<Rational>> project(const std::vector<ClipPoint>& corners) {
  std::vector<Vec2<Rational>> s;
  for (const ClipPoint& c : corners) {
    if (sgn(c[3]) <= 0) throw std::logic_error("interp oracle: projecting a corner with w <= 0");
    s.push_back({Rational(c[0] / c[3]), Rational(c[1] / c[3])});
  }
  return s;
}

Rational perspective_at(const std::array<ClipPoint, 3>& v, const std::array<Rational, 3>& f, const Vec2<Rational>& s) {
  // Columns (x_k, y_k, w_k); solve M b' = (s_x, s_y, 1) by Cramer's rule. b' = b / W for the point's
  // own w = W, so b = b' / sum b'.
  auto col = [&](int k, int row) -> Rational { return row == 0 ? v[k][0] : row == 1 ? v[k][1] : v[k][3]; };
  const std::array<Rational, 3> rhs{s.x, s.y, 1};
  auto m = [&](int row, int k, int replaced) -> Rational { return k == replaced ? rhs[row] : col(k, row); };
  auto det = [&](int replaced) -> Rational {
    return det3(m(0, 0, replaced), m(0, 1, replaced), m(0, 2, replaced), m(1, 0, replaced), m(1, 1, replaced), m(1, 2, replaced), m(2, 0, replaced),
                m(2, 1, replaced), m(2, 2, replaced));
  };
  const Rational d = det(-1);
  if (sgn(d) == 0) throw std::logic_error("interp oracle: the triangle's plane passes through the eye");
  Rational num = 0, den = 0;
  for (int k = 0; k < 3; ++k) {
    const Rational b = det(k) / d;
    num += b * f[k], den += b;
  }
  return num / den;
}

InterpSamples perspective_samples(const std::array<ClipPoint, 3>& v, const std::array<std::vector<Rational>, 3>& attrs, const Rational& w_near) {
  InterpSamples out;
  const ClippedPolygon poly = clip_w(v, attrs, w_near);
  if (poly.corners.size() < 3) return out;
  out.pixels = polygon_samples(ring_of(project(poly.corners)), FillRule::nonzero);
  for (const Pixel& p : out.pixels)
    for (std::size_t c = 0; c < attrs[0].size(); ++c)
      out.values.push_back(perspective_at(v, {attrs[0][c], attrs[1][c], attrs[2][c]}, {Rational(p.x), Rational(p.y)}));
  return out;
}

InterpSamples affine_samples(const std::array<ClipPoint, 3>& v, const std::array<std::vector<Rational>, 3>& attrs, const Rational& w_near) {
  InterpSamples out;
  const ClippedPolygon poly = clip_w(v, attrs, w_near);
  if (poly.corners.size() < 3) return out;
  const std::vector<Vec2<Rational>> s = project(poly.corners);
  out.pixels = polygon_samples(ring_of(s), FillRule::nonzero);
  // Each fan triangle's own covered set: by the tiling property exactly one holds each sample.
  std::vector<std::array<Vec2<Rational>, 3>> fan;
  std::vector<std::vector<Pixel>> covers;
  for (std::size_t f = 1; f + 1 < s.size(); ++f) {
    fan.push_back({s[0], s[f], s[f + 1]});
    covers.push_back(triangle_samples(fan.back()));
  }
  auto row_major = [](Pixel a, Pixel b) { return std::pair(a.y, a.x) < std::pair(b.y, b.x); };
  for (const Pixel& p : out.pixels) {
    std::size_t f = 0;
    while (f < fan.size() && !std::binary_search(covers[f].begin(), covers[f].end(), p, row_major)) ++f;
    if (f == fan.size()) throw std::logic_error("interp oracle: a covered sample in no fan triangle");
    for (std::size_t c = 0; c < attrs[0].size(); ++c)
      out.values.push_back(linear_at(fan[f], {poly.attrs[0][c], poly.attrs[f + 1][c], poly.attrs[f + 2][c]}, p));
  }
  return out;
}

}  // namespace sw::oracle
