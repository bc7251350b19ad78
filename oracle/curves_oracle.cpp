#include "curves_oracle.hpp"
#include <algorithm>
#include <set>
#include <stdexcept>
#include "cgal_bridge.hpp"

namespace sw::oracle {
namespace {

// round(v) = floor(v + 1/2), exactly; throws if the result does not fit a pixel index.
std::int64_t round_q(const Q& v) {
  const Rational w = r(v + Q(1, 2));
  mpz_class f;
  mpz_fdiv_q(f.get_mpz_t(), w.get_num_mpz_t(), w.get_den_mpz_t());
  if (mpz_sizeinbase(f.get_mpz_t(), 2) > 63) throw std::overflow_error("poly_pixels: round(y) out of int64 range");
  return num::int64_of(f);
}

// --- Per-row statements, on GMP integers. Each row is computed on its own from r and y. ---

// X(y) of the midpoint circle. For D = r^2 - y^2 > 0 the odd square (2k - 1)^2 never equals the
// even 4D, so (2k - 1)^2 < 4D iff 2k - 1 <= isqrt(4D): k = (isqrt(4D) + 1) / 2. The two loops only
// re-establish the definition's two inequalities should that reasoning ever be off; they never run.
std::int64_t midpoint_row(const mpz_class& r, std::int64_t y) {
  const mpz_class yy = num::mpz_of(y);
  const mpz_class four_d = 4 * (r * r - yy * yy);
  if (four_d <= 0) return 0;  // only the k == 0 clause holds
  mpz_class k = (sqrt(four_d) + 1) / 2;
  auto sq = [](const mpz_class& m) { return mpz_class(m * m); };
  while (k > 0 && sq(2 * k - 1) >= four_d) --k;
  while (sq(2 * k + 1) < four_d) ++k;
  return num::int64_of(k);
}

// I(y) of the interior border: isqrt(r^2 - y^2), or -1 when r^2 - y^2 < 0 (no k >= 0 exists).
std::int64_t interior_row(const mpz_class& r, std::int64_t y) {
  const mpz_class yy = num::mpz_of(y);
  const mpz_class d = r * r - yy * yy;
  if (d < 0) return -1;
  mpz_class k = sqrt(d);
  while (k > 0 && k * k > d) --k;
  while ((k + 1) * (k + 1) <= d) ++k;
  return num::int64_of(k);
}

// O's rows y = 0, 1, ... while y <= row(y), their 8 mirror images moved to the centre, distinct and
// sorted. row(y) <= r, so at most r + 1 rows are visited.
template <class Row> std::vector<Pixel> octant_images(std::int64_t cx, std::int64_t cy, std::int64_t r, Row row) {
  std::vector<Pixel> out;
  if (r < 0) return out;
  const mpz_class rz = num::mpz_of(r);
  for (std::int64_t y = 0;; ++y) {
    const std::int64_t k = row(rz, y);
    if (y > k) break;
    const std::int64_t x = -k;
    for (const Pixel p : {Pixel{x, y}, Pixel{-x, y}, Pixel{x, -y}, Pixel{-x, -y}, Pixel{y, x}, Pixel{-y, x},
                          Pixel{y, -x}, Pixel{-y, -x}})
      out.push_back({cx + p.x, cy + p.y});
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// --- Brute-force statements, on __int128 (squares of anything below 2^62 fit). Small r only. ---

__extension__ typedef __int128 I128;  // GCC/Clang extension; marked so -Wpedantic stays quiet

// X(t) for t = 0 .. r + 1 by scanning every candidate: the k >= 1 whose odd neighbours bracket 4D,
// (2k - 1)^2 < 4D < (2k + 1)^2; 0 when no k does (D <= 0).
std::vector<std::int64_t> midpoint_table(std::int64_t r) {
  std::vector<std::int64_t> t(static_cast<std::size_t>(r + 2), 0);
  for (std::int64_t i = 0; i <= r + 1; ++i) {
    const I128 four_d = 4 * (I128(r) * r - I128(i) * i);
    for (std::int64_t k = 1; k <= r + 1; ++k) {
      const I128 lo = I128(2 * k - 1) * (2 * k - 1), hi = I128(2 * k + 1) * (2 * k + 1);
      if (lo < four_d && four_d < hi) t[static_cast<std::size_t>(i)] = k;
    }
  }
  return t;
}

// I(t) for t = 0 .. r + 1 by scanning: the k >= 0 with k^2 <= D < (k + 1)^2; -1 when D < 0.
std::vector<std::int64_t> interior_table(std::int64_t r) {
  std::vector<std::int64_t> t(static_cast<std::size_t>(r + 2), -1);
  for (std::int64_t i = 0; i <= r + 1; ++i) {
    const I128 d = I128(r) * r - I128(i) * i;
    for (std::int64_t k = 0; k <= r + 1; ++k)
      if (I128(k) * k <= d && d < I128(k + 1) * (k + 1)) t[static_cast<std::size_t>(i)] = k;
  }
  return t;
}

// Keeps each pixel of the box that is its row's pixel in the flat part (|y| <= |x|) or its
// column's pixel in the steep part (|x| <= |y|). Scanning x then y ascending yields sorted output.
std::vector<Pixel> box_scan(std::int64_t cx, std::int64_t cy, std::int64_t r, const std::vector<std::int64_t>& t) {
  std::vector<Pixel> out;
  if (r < 0) return out;
  const auto at = [&](std::int64_t i) { return t[static_cast<std::size_t>(i)]; };
  for (std::int64_t x = -r - 1; x <= r + 1; ++x)
    for (std::int64_t y = -r - 1; y <= r + 1; ++y) {
      const std::int64_t ax = x < 0 ? -x : x, ay = y < 0 ? -y : y;
      if ((ay <= ax && ax == at(ay)) || (ax <= ay && ay == at(ax))) out.push_back({cx + x, cy + y});
    }
  return out;
}

}  // namespace

std::vector<Pixel> poly_pixels(const std::array<Rational, 4>& coeffs, std::int64_t xs, std::int64_t xe) {
  const Q a = q(coeffs[0]), b = q(coeffs[1]), c = q(coeffs[2]), d = q(coeffs[3]);
  std::vector<Pixel> out;
  for (std::int64_t x = xs; x < xe; ++x) {  // x < xe, so ++x cannot overflow
    const Q v(x);
    // Each power from scratch: nothing is carried between columns.
    out.push_back({x, round_q(a * v * v * v + b * v * v + c * v + d)});
  }
  return out;
}

std::vector<Pixel> circle_midpoint_pixels(std::int64_t cx, std::int64_t cy, std::int64_t r) {
  return octant_images(cx, cy, r, midpoint_row);
}

std::vector<Pixel> circle_interior_pixels(std::int64_t cx, std::int64_t cy, std::int64_t r) {
  return octant_images(cx, cy, r, interior_row);
}

std::vector<Pixel> circle_midpoint_brute_force(std::int64_t cx, std::int64_t cy, std::int64_t r) {
  if (r < 0) return {};
  return box_scan(cx, cy, r, midpoint_table(r));
}

std::vector<Pixel> circle_interior_brute_force(std::int64_t cx, std::int64_t cy, std::int64_t r) {
  if (r < 0) return {};
  return box_scan(cx, cy, r, interior_table(r));
}

std::vector<Pixel> implicit_walk_pixels(const std::array<std::array<Rational, 4>, 4>& c, Pixel start, std::int64_t max_steps,
                                        ImplicitWalkEnd* end) {
  // sum c_ij * (d/dx)^dx (d/dy)^dy (x^i y^j) at (x, y), term by term from the powers of x and y.
  auto eval = [&](const Rational& x, const Rational& y, int dx, int dy) {
    const std::array<Rational, 4> xp{Rational(1), x, Rational(x * x), Rational(x * x * x)},
        yp{Rational(1), y, Rational(y * y), Rational(y * y * y)};
    Rational s = 0;
    for (int i = dx; i < 4; ++i)
      for (int j = dy; i + j < 4; ++j)
        if (c[i][j] != 0) s += c[i][j] * (dx ? i : 1) * (dy ? j : 1) * xp[i - dx] * yp[j - dy];
    return s;
  };
  auto sign = [](const Rational& v) { return sgn(v); };
  std::vector<Pixel> path{start};
  std::set<Pixel> on_path{start};
  Pixel p = start;
  std::int64_t moves = 0;
  std::string why;
  while (why.empty()) {
    if (moves == max_steps) {
      why = "max_steps";
      break;
    }
    const Rational px(p.x), py(p.y), gx = eval(px, py, 1, 0), gy = eval(px, py, 0, 1);
    if (sign(gx) == 0 && sign(gy) == 0) {
      why = "singular";
      break;
    }
    const Rational tx = -gy, ty = gx;
    const int cmp = sign(Rational(tx * tx - ty * ty));  // |t_x| vs |t_y|
    const bool x_major = cmp > 0 || (cmp == 0 && sign(tx) * sign(ty) < 0);
    const int sa = sign(x_major ? tx : ty), gb = sign(x_major ? gy : gx);
    const int sb = sign(x_major ? ty : tx) != 0 ? sign(x_major ? ty : tx) : -gb;
    const Pixel A = x_major ? Pixel{p.x + sa, p.y} : Pixel{p.x, p.y + sa};
    const Pixel D = x_major ? Pixel{A.x, A.y + sb} : Pixel{A.x + sb, A.y};
    const Rational mx = Rational(A.x + D.x) / 2, my = Rational(A.y + D.y) / 2;
    const Pixel next = sign(eval(mx, my, 0, 0)) * sb * gb < 0 ? D : A;
    ++moves;
    if (next == start) why = "closed";
    else if (!on_path.insert(next).second) why = "revisit";
    else path.push_back(p = next);
  }
  if (end) *end = {why, moves};
  return path;
}

}  // namespace sw::oracle
