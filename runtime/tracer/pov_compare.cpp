#include "tracer/pov_compare.hpp"
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include "png.hpp"
#include "rays/camera_ray.hpp"
#include "rays_oracle.hpp"
#include "tracer/pov_export.hpp"

namespace sw::tracer {

namespace {

using Q = Rational;
using Q3 = Vec3<Rational>;

Vec3<double> to_d(const Q3& v) { return {v.x.get_d(), v.y.get_d(), v.z.get_d()}; }

ray::Ray3<Q> exact_ray(const Scene& s, std::int64_t w, std::int64_t h, std::int64_t i, std::int64_t j) {
  const Camera& c = s.camera;
  ray::Camera<Q> rc;
  rc.eye = c.eye.q, rc.vpn = c.vpn.q, rc.vup = c.vup.q, rc.dist = c.dist.q;
  rc.fov = c.has_window ? Q(0) : Q(c.fov.q * num::pi<Q>() / 180);
  rc.width = w, rc.height = h, rc.projection = c.projection, rc.has_window = c.has_window;
  for (std::size_t k = 0; k < 4; ++k) rc.window[k] = c.window[k].q;
  NoProbe none;
  return ray::camera_ray<Q>(rc, i, j, none).ray;
}

std::array<Q3, 3> mesh_triangle(const Scene& s, const Object& ob, std::size_t t) {
  const spatial::Mesh& m = *s.meshes[static_cast<std::size_t>(ob.mesh)].mesh;
  std::array<Q3, 3> v;
  for (std::size_t c = 0; c < 3; ++c) {
    const auto& x = m.v[static_cast<std::size_t>(m.f[t][c])];
    v[c] = Q3{Q(ob.scale.q * Q(x[0])), Q(ob.scale.q * Q(x[1])), Q(ob.scale.q * Q(x[2]))} + ob.translate.q;
  }
  return v;
}

// A double filter for the exact mesh test: a triangle is a candidate unless the ray clearly misses
// it (a barycentric below -1e-6 relative, or the triangle behind or beyond t_max by 1e-6 relative).
bool near_triangle(const Vec3<double>& o, const Vec3<double>& d, const std::array<Vec3<double>, 3>& v, double t_max) {
  const Vec3<double> e1 = v[1] - v[0], e2 = v[2] - v[0], p = cross(d, e2);
  const double det = dot(e1, p), scale = std::sqrt(dot(e1, e1) * dot(e2, e2) * dot(d, d));
  if (std::abs(det) <= 1e-9 * scale) return true;  // nearly parallel: let the exact test decide
  const Vec3<double> s = o - v[0], q = cross(s, e1);
  const double u = dot(s, p) / det, w = dot(d, q) / det, t = dot(e2, q) / det, tol = 1e-6;
  return u >= -tol && w >= -tol && u + w <= 1 + tol && t >= -tol * (1 + std::abs(t)) && t <= t_max * (1 + tol) + tol;
}

struct ExactHit {
  bool hit = false;
  Q t;
  int prim = -1;  // a mesh's triangle
};

// Object k against the ray; for meshes the nearest triangle with t < t_max (candidates only).
ExactHit exact_object(const Scene& s, std::size_t k, const ray::Ray3<Q>& r, double t_max, int skip_prim = -1) {
  const Object& ob = s.objects[k];
  ExactHit out;
  auto take = [&](const oracle::RayResult& x, int prim) {
    if (x.hit && (!out.hit || x.t < out.t)) out.hit = true, out.t = x.t, out.prim = prim;
  };
  switch (ob.kind) {
    case Shape::sphere: take(oracle::ray_sphere(r.o, r.d, ob.a.q, ob.radius.q), -1); break;
    case Shape::plane: take(oracle::ray_plane(r.o, r.d, ob.a.q, ob.b.q), -1); break;
    case Shape::box: take(oracle::ray_box(r.o, r.d, ob.a.q, ob.b.q), -1); break;
    case Shape::triangle: take(oracle::ray_triangle(r.o, r.d, {ob.v[0].q, ob.v[1].q, ob.v[2].q}), -1); break;
    case Shape::mesh: {
      const spatial::Mesh& m = *s.meshes[static_cast<std::size_t>(ob.mesh)].mesh;
      const Vec3<double> od = to_d(r.o), dd = to_d(r.d);
      for (std::size_t t = 0; t < m.size(); ++t) {
        if (static_cast<int>(t) == skip_prim) continue;
        const std::array<Q3, 3> v = mesh_triangle(s, ob, t);
        if (!near_triangle(od, dd, {to_d(v[0]), to_d(v[1]), to_d(v[2])}, t_max)) continue;
        take(oracle::ray_triangle(r.o, r.d, v), static_cast<int>(t));
      }
      break;
    }
  }
  return out;
}

struct FirstHits {
  std::vector<int> objects;
  Q t;
  int prim = -1;
};

FirstHits first_hits(const Scene& s, const ray::Ray3<Q>& r) {
  FirstHits f;
  for (std::size_t k = 0; k < s.objects.size(); ++k) {
    const ExactHit x = exact_object(s, k, r, std::numeric_limits<double>::infinity());
    if (!x.hit) continue;
    if (f.objects.empty() || x.t < f.t) f.objects = {static_cast<int>(k)}, f.t = x.t, f.prim = x.prim;
    else if (x.t == f.t) f.objects.push_back(static_cast<int>(k));
  }
  return f;
}

bool neighbour_differs(const std::vector<int>& m, std::int64_t w, std::int64_t h, std::int64_t i, std::int64_t j) {
  for (std::int64_t dj = -1; dj <= 1; ++dj)
    for (std::int64_t di = -1; di <= 1; ++di) {
      const std::int64_t x = i + di, y = j + dj;
      if (x >= 0 && y >= 0 && x < w && y < h && m[static_cast<std::size_t>(y * w + x)] != m[static_cast<std::size_t>(j * w + i)])
        return true;
    }
  return false;
}

}  // namespace

std::vector<int> exact_first_hits(const Scene& s, std::int64_t w, std::int64_t h, std::int64_t i, std::int64_t j) {
  return first_hits(s, exact_ray(s, w, h, i, j)).objects;
}

int exact_lit(const Scene& s, std::int64_t w, std::int64_t h, std::int64_t i, std::int64_t j, std::size_t light) {
  const ray::Ray3<Q> r = exact_ray(s, w, h, i, j);
  const FirstHits f = first_hits(s, r);
  if (f.objects.size() != 1) return -1;
  const std::size_t k = static_cast<std::size_t>(f.objects[0]);
  const Object& ob = s.objects[k];
  const Q3 p = r.o + f.t * r.d;
  Q3 n;
  switch (ob.kind) {
    case Shape::sphere: n = p - ob.a.q; break;
    case Shape::plane: n = ob.b.q; break;
    case Shape::box: {
      int faces = 0;
      for (int a = 0; a < 3; ++a)
        if (p[a] == ob.a.q[a] || p[a] == ob.b.q[a]) ++faces, n = Q3{}, n[a] = p[a] == ob.a.q[a] ? Q(-1) : Q(1);
      if (faces != 1) return -1;  // an edge or a corner: no one normal
      break;
    }
    case Shape::triangle: n = cross(Q3(ob.v[1].q - ob.v[0].q), Q3(ob.v[2].q - ob.v[0].q)); break;
    case Shape::mesh: {
      const auto v = mesh_triangle(s, ob, static_cast<std::size_t>(f.prim));
      n = cross(Q3(v[1] - v[0]), Q3(v[2] - v[0]));
      break;
    }
  }
  if (sgn(dot(r.d, n)) > 0) n = Q(-1) * n;
  const lighting::Light<Q>& li = s.lights[light];
  const bool positional = li.type != lighting::LightType::directional;
  const Q3 to_light = positional ? Q3(li.where - p) : li.where;
  if (sgn(dot(n, to_light)) <= 0) return 0;
  const ray::Ray3<Q> sr{p, to_light};
  const double t_max = positional ? 1.0 : std::numeric_limits<double>::infinity();
  for (std::size_t o = 0; o < s.objects.size(); ++o) {
    const bool self = o == k;
    if (self && (ob.kind == Shape::plane || ob.kind == Shape::triangle)) continue;  // a ray leaves its plane
    const ExactHit x = exact_object(s, o, sr, t_max, self ? f.prim : -1);
    // A sphere's point is rounded to 128 bits: its own surface re-met within 2^-64 is that rounding.
    if (!x.hit || (self && ob.kind == Shape::sphere && x.t < Q(1) / Q(std::ldexp(1.0, 64)))) continue;
    if (!positional || x.t < 1) return 0;
  }
  return 1;
}

IdCounts compare_ids(const Scene& s, std::int64_t w, std::int64_t h, const std::vector<int>& ours, const std::vector<int>& pov) {
  IdCounts c;
  c.pixels = ours.size();
  for (std::int64_t j = 0; j < h; ++j)
    for (std::int64_t i = 0; i < w; ++i) {
      const std::size_t p = static_cast<std::size_t>(j * w + i);
      if (pov[p] == -2) ++c.unknown_colour;
      if (ours[p] == pov[p]) continue;
      ++c.differ;
      const std::vector<int> e = exact_first_hits(s, w, h, i, j);
      auto right = [&](int id) { return e.empty() ? id == -1 : std::find(e.begin(), e.end(), id) != e.end(); };
      const bool a = right(ours[p]), b = right(pov[p]);
      if (a && b) ++c.both_right;
      else if (a) ++c.ours_right;
      else if (b) ++c.pov_right;
      else ++c.both_wrong;
      const bool sil = neighbour_differs(ours, w, h, i, j) || neighbour_differs(pov, w, h, i, j);
      if (sil) ++c.silhouette;
      else if (!b) ++c.pov_wrong_inside;
      else ++c.unexplained;
    }
  return c;
}

ShadowCounts compare_shadows(const Scene& s, std::int64_t w, std::int64_t h, std::size_t light, const std::vector<int>& ours_ids,
                             const std::vector<int>& pov_ids, const std::vector<char>& ours_lit,
                             const std::vector<double>& cosine, const std::vector<char>& pov_lit) {
  ShadowCounts c;
  std::vector<int> mask(ours_lit.begin(), ours_lit.end());
  for (std::int64_t j = 0; j < h; ++j)
    for (std::int64_t i = 0; i < w; ++i) {
      const std::size_t p = static_cast<std::size_t>(j * w + i);
      if (ours_ids[p] < 0 || ours_ids[p] != pov_ids[p]) continue;
      ++c.compared;
      if (ours_lit[p] == pov_lit[p]) continue;
      ++c.differ;
      if (std::abs(cosine[p]) < 2.0 / 255) {
        ++c.grazing;
        continue;
      }
      const bool edge = neighbour_differs(mask, w, h, i, j);
      if (edge) ++c.silhouette;
      const int e = exact_lit(s, w, h, i, j, light);
      if (e < 0) ++c.undecided;
      else if (e == ours_lit[p]) ++c.ours_right;
      else ++c.pov_right, c.unexplained += !edge;
    }
  return c;
}

bool povray_available() { return std::system("povray --version >/dev/null 2>&1") == 0; }

double run_povray(const std::string& pov, const std::string& png, std::int64_t w, std::int64_t h) {
  std::string cmd;
  auto quote = [](const std::string& a) {
    std::string q = "'";
    for (const char ch : a) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return q + "'";
  };
  for (const std::string& a : povray_args(pov, png, w, h)) cmd += quote(a) + " ";
  const std::string log = png + ".log";
  std::filesystem::remove(png);
  const auto start = std::chrono::steady_clock::now();
  const int rc = std::system((cmd + "> " + quote(log) + " 2>&1").c_str());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (rc != 0 || !std::filesystem::exists(png)) {
    std::ifstream in(log);
    std::stringstream all;
    all << in.rdbuf();
    std::string text = all.str();
    if (text.size() > 300) text = text.substr(text.size() - 300);
    for (char& ch : text)
      if (ch == '\n') ch = ' ';
    throw InputError("povray failed on " + pov + ": " + text);
  }
  return seconds;
}

std::vector<int> read_pov_ids(const std::string& png) {
  const PngImage img = read_png_rgb(png);
  std::vector<int> ids(img.rgb.size() / 3);
  for (std::size_t p = 0; p < ids.size(); ++p) ids[p] = pov_id_of(img.rgb[3 * p], img.rgb[3 * p + 1], img.rgb[3 * p + 2]);
  return ids;
}

std::vector<char> read_pov_lit(const std::string& png) {
  const PngImage img = read_png_rgb(png);
  std::vector<char> lit(img.rgb.size() / 3);
  for (std::size_t p = 0; p < lit.size(); ++p) lit[p] = (img.rgb[3 * p] | img.rgb[3 * p + 1] | img.rgb[3 * p + 2]) != 0;
  return lit;
}

double psnr(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  double se = 0;
  for (std::size_t k = 0; k < a.size(); ++k) se += (double(a[k]) - double(b[k])) * (double(a[k]) - double(b[k]));
  if (se == 0) return std::numeric_limits<double>::infinity();
  return 10 * std::log10(255.0 * 255.0 / (se / double(a.size())));
}

}  // namespace sw::tracer
