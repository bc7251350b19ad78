#include "fill_common.hpp"
#include <algorithm>
#include <iterator>
#include "fill_oracle.hpp"
#include "pixels.hpp"

namespace sw::fillspec {

Json fill_json(const FillOutput& o) {
  Json r = pixels_json("pixels", {o.pixels});
  if (o.n == 0) return r;
  Json vs = Json::array();
  for (std::size_t p = 0; p < o.pixels.size(); ++p) vs.push_back(std::vector<double>(o.values.begin() + p * o.n, o.values.begin() + (p + 1) * o.n));
  r["values"] = std::move(vs);
  return r;
}

double wrong_pixels(const FillOutput& got, const FillOutput& exact) {
  std::vector<Pixel> a = got.pixels, b = exact.pixels, diff;
  auto row_major = [](Pixel p, Pixel q) { return std::pair(p.y, p.x) < std::pair(q.y, q.x); };
  std::sort(a.begin(), a.end(), row_major);
  std::sort(b.begin(), b.end(), row_major);
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(diff), row_major);
  return static_cast<double>(diff.size());
}

Vec2<Rational> parse_vertex(const Json& v, const std::string& what, double bound) {
  if (!v.is_array() || v.size() != 2) throw InputError(what + ": expected [x, y]");
  Vec2<Rational> p;
  for (int a = 0; a < 2; ++a) {
    const std::string w = what + "[" + std::to_string(a) + "]";
    p[a] = parse_rational(v[a], w);
    check_bound(p[a], bound, w);
    check_digits(p[a], w);
  }
  return p;
}

double box_samples(const std::vector<Vec2<Rational>>& pts) {
  if (pts.empty()) return 0;
  Rational lo[2] = {pts[0].x, pts[0].y}, hi[2] = {pts[0].x, pts[0].y};
  for (const auto& p : pts)
    for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  const double w = std::max<double>(0, double(num::floor_int(hi[0]) - num::ceil_int(lo[0]) + 1));
  const double h = std::max<double>(0, double(num::floor_int(hi[1]) - num::ceil_int(lo[1]) + 1));
  return w * h;
}

void check_budget(const std::vector<Vec2<Rational>>& pts, const std::string& what) {
  const double n = box_samples(pts);
  if (n > kMaxSamples) throw InputError(what + ": its bounding box holds " + std::to_string(static_cast<long long>(n)) + " samples, more than the budget of 2^20");
}

// input.attrs: one list of 1 to 8 numbers per vertex, all of one length.
std::vector<std::vector<Rational>> parse_attrs(const Json& a, std::size_t vertices) {
  if (!a.is_array() || a.size() != vertices)
    throw InputError("input.attrs: expected one list of numbers per vertex (" + std::to_string(vertices) + " lists)");
  std::vector<std::vector<Rational>> out;
  for (std::size_t k = 0; k < vertices; ++k) {
    const std::string what = "input.attrs[" + std::to_string(k) + "]";
    if (!a[k].is_array() || a[k].empty() || a[k].size() > fill::kMaxAttrs) throw InputError(what + ": expected a list of 1 to 8 numbers");
    if (k > 0 && a[k].size() != a[0].size())
      throw InputError(what + ": has " + std::to_string(a[k].size()) + " values, input.attrs[0] has " + std::to_string(a[0].size()) + " (every vertex needs the same count)");
    out.emplace_back();
    for (std::size_t c = 0; c < a[k].size(); ++c) {
      const std::string w = what + "[" + std::to_string(c) + "]";
      out.back().push_back(parse_rational(a[k][c], w));
      check_bound(out.back().back(), kCoordBound, w);
      check_digits(out.back().back(), w);
    }
  }
  return out;
}

FillOutput plane_values(std::vector<Pixel> pixels, const std::array<Vec2<Rational>, 3>& v, const std::vector<std::vector<Rational>>& attrs) {
  FillOutput o{std::move(pixels), attrs.empty() ? 0 : attrs[0].size(), {}, {}};
  for (const Pixel& p : o.pixels)
    for (std::size_t c = 0; c < o.n; ++c) o.exact_values.push_back(oracle::linear_at(v, {attrs[0][c], attrs[1][c], attrs[2][c]}, p));
  for (const Rational& x : o.exact_values) o.values.push_back(x.get_d());
  return o;
}

}  // namespace sw::fillspec
