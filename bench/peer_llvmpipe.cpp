// The fill family's real peer, Mesa's llvmpipe through OSMesa (docs/fill/llvmpipe.md):
//  1. the fill convention, found by experiment: the hard cases drawn as given and mirrored in y;
//  2. >= 10^5 random and hard triangles on llvmpipe's 1/256 grid: differing pixels against the
//     exact oracle (goal 0), each classified; the catalog's fills against llvmpipe too;
//  3. triangles off the grid (1/4096): llvmpipe snaps them, and the exact oracle classifies why;
//  4. fill rate with LP_NUM_THREADS=1 at 8, 128 and 2048 px^2 against untraced triangle-edge.
// Usage: peer_llvmpipe [triangles (default 100000)]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include "fill/triangle_edge.hpp"
#include "llvmpipe_peer.hpp"

using namespace sw;
using namespace sw::peer;

namespace {

// No y flip: in GL window coordinates (y up) llvmpipe keeps samples on left and bottom edges, which
// is our (eps, eps^2) rule; the experiment below shows it (docs/fill/llvmpipe.md).
constexpr bool kMirror = false;

// The square [0, 4]^2 split along its diagonal: which triangle llvmpipe gives each sample to, drawn
// as given and mirrored. Prints rows top down: L lower triangle, U upper, . neither, 2 both.
void square_experiment(Llvmpipe& gl) {
  const auto n = [](std::int64_t px) { return px * kDen; };
  const Tri lower{{{{n(0), n(0)}, {n(4), n(0)}, {n(4), n(4)}}}}, upper{{{{n(0), n(0)}, {n(4), n(4)}, {n(0), n(4)}}}};
  const std::vector<Group> groups{Group{{lower}, "lower"}, Group{{upper}, "upper"}};
  std::printf("square [0,4]^2 cut along y = x; rows j = 4 .. 0, columns i = 0 .. 4 (L lower, U upper)\n");
  for (const bool mirror : {false, true}) {
    const auto covered = gl.cover(groups, mirror);
    std::printf("  %s:\n", mirror ? "drawn mirrored in y" : "drawn as given    ");
    for (std::int64_t j = 4; j >= 0; --j) {
      std::printf("    j=%lld  ", (long long)j);
      for (std::int64_t i = 0; i <= 4; ++i) {
        const bool in_lower = covered[0].count(Pixel{i, j}) > 0, in_upper = covered[1].count(Pixel{i, j}) > 0;
        std::printf("%c", in_lower && in_upper ? '2' : in_lower ? 'L' : in_upper ? 'U' : '.');
      }
      std::printf("\n");
    }
  }
  std::printf("  exact rule: the bottom row j = 0 and the diagonal belong to L, column i = 0 above it to U\n\n");
}

void print_comparison(const char* title, const Comparison& c) {
  std::printf("%s\n  triangles %zu (groups %zu), exact covered pixels %zu, differing pixels %zu\n", title, c.triangles, c.groups,
              c.exact_pixels, c.differing);
  for (const auto& [why, n] : c.classes) std::printf("    class  %-48s %zu\n", why.c_str(), n);
  for (const auto& [kind, n] : c.kinds) std::printf("    kind   %-48s %zu\n", kind.c_str(), n);
  for (const auto& d : c.examples)
    std::printf("    e.g. group %zu sample (%lld, %lld): llvmpipe %d, exact %d (%s)\n", d.group, (long long)d.sample.x,
                (long long)d.sample.y, d.llvmpipe, d.exact, d.why.c_str());
}

// The catalog's fill (if registered) against llvmpipe on the single triangles.
void print_catalog(Llvmpipe& gl, const std::vector<Group>& groups, const char* id) {
  const CatalogComparison c = compare_catalog(gl, groups, id, kMirror);
  if (!c.found) {
    std::printf("%s: not in the catalog yet, skipped\n", id);
    return;
  }
  std::printf("%s (%s) against llvmpipe: %zu single triangles, %zu pixels, differing pixels %zu, errors %zu%s%s\n", id,
              c.numeric.c_str(), c.triangles, c.pixels, c.differing, c.errors,
              c.first_error.empty() ? "" : ", first: ", c.first_error.c_str());
}

// ---- fill rate ----

struct RateSet {
  std::vector<Tri> tris;   // our coordinates, on the 1/256 grid, inside the framebuffer's samples
  std::size_t pixels = 0;  // exact covered samples
};

// n triangles of about `area` px^2 (jittered equilateral, random orientation) at random places.
RateSet rate_set(double area, std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  const double radius = std::sqrt(4 * area / (3 * std::sqrt(3.0)));
  const double margin = radius + 2, span = Llvmpipe::kFb - 2 * margin - 1;
  RateSet set;
  for (std::size_t k = 0; k < n; ++k) {
    const double cx = margin + span * unit(rng), cy = margin + span * unit(rng), turn = 2 * M_PI * unit(rng);
    Tri t;
    for (int v = 0; v < 3; ++v) {
      const double angle = turn + 2 * M_PI * v / 3 + 0.3 * (unit(rng) - 0.5);
      t.v[std::size_t(v)] = {std::llround((cx + radius * std::cos(angle)) * 256) * kSnap,
                             std::llround((cy + radius * std::sin(angle)) * 256) * kSnap};
    }
    set.pixels += oracle_samples(t).size();
    set.tris.push_back(t);
  }
  return set;
}

template <class Num> std::vector<fill::EdgeTriangle<Num>> edge_triangles(const RateSet& set) {
  std::vector<fill::EdgeTriangle<Num>> tris;
  for (const Tri& t : set.tris) {
    fill::EdgeTriangle<Num> e;
    for (int v = 0; v < 3; ++v) {
      const auto& p = t.v[std::size_t(v)];
      if constexpr (std::is_same_v<Num, std::int64_t>) e.v[std::size_t(v)] = {p[0] / kSnap, p[1] / kSnap}, e.unit = 256;
      else e.v[std::size_t(v)] = {Num(double(p[0]) / kDen), Num(double(p[1]) / kDen)};
    }
    tris.push_back(e);
  }
  return tris;
}

// One pass of our untraced triangle-edge (fixed point: int64, unit 1/256; or double). to_buffer:
// each triangle's pixels (a reused vector) are written as colour into a 1024^2 RGBA buffer, the work
// llvmpipe does; otherwise all pixels are appended to one list. Returns seconds; counts the pixels.
template <class Num> double time_ours(const std::vector<fill::EdgeTriangle<Num>>& tris, bool to_buffer, std::vector<Pixel>& out,
                                      std::vector<std::uint32_t>& buffer, std::size_t& pixels) {
  NoProbe none;
  const auto t0 = std::chrono::steady_clock::now();
  out.clear();
  pixels = 0;
  for (const auto& e : tris) {
    if (to_buffer) out.clear();
    fill::triangle_edge<Num>(e, out, none);
    if (!to_buffer) continue;
    for (const Pixel& p : out) buffer[std::size_t(p.y) * Llvmpipe::kFb + std::size_t(p.x)] = 0xff2878c8u;
    pixels += out.size();
  }
  if (!to_buffer) pixels = out.size();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void fill_rate(Llvmpipe& gl) {
  std::printf("\nfill rate, LP_NUM_THREADS=%s, one glDrawArrays per pass then glFinish, best of 7 interleaved passes\n",
              std::getenv("LP_NUM_THREADS"));
  std::printf("  ours: untraced triangle-edge, 'fb' writes colour into a 1024^2 RGBA buffer, 'list' appends to one vector\n");
  std::printf("  %-6s %-7s %-9s %-10s %-10s %-10s %-10s %-8s %-8s %-8s\n", "area", "tris", "pixels", "llvmpipe", "int fb",
              "double fb", "int list", "int fb", "dbl fb", "int list");
  std::printf("  %-6s %-7s %-9s %-43s %s\n", "px^2", "", "", "pixels per second", "ratio to llvmpipe");
  struct Size {
    double area;
    std::size_t n;
  };
  for (const Size s : {Size{8, 200000}, Size{128, 20000}, Size{2048, 2000}}) {
    const RateSet set = rate_set(s.area, s.n, 99 + std::uint64_t(s.area));
    std::vector<float> verts;
    for (const Tri& t : set.tris)
      for (const auto& p : t.v)
        for (int a = 0; a < 2; ++a) verts.push_back(Llvmpipe::ndc(double(p[std::size_t(a)]) / kDen + 0.5));
    const auto int_tris = edge_triangles<std::int64_t>(set);
    const auto dbl_tris = edge_triangles<double>(set);
    std::vector<Pixel> out;
    out.reserve(set.pixels + 16);
    std::vector<std::uint32_t> buffer(std::size_t(Llvmpipe::kFb) * Llvmpipe::kFb);
    gl.time_draw(verts, 1);  // warm up: shader compilation
    // Passes interleaved, so that a change of load on a shared machine hits every side alike.
    double lp = 1e30, int_fb = 1e30, dbl_fb = 1e30, int_list = 1e30;
    std::array<std::size_t, 3> pixels{};
    for (int pass = 0; pass < 7; ++pass) {
      lp = std::min(lp, gl.time_draw(verts, 1));
      int_fb = std::min(int_fb, time_ours(int_tris, true, out, buffer, pixels[0]));
      dbl_fb = std::min(dbl_fb, time_ours(dbl_tris, true, out, buffer, pixels[1]));
      int_list = std::min(int_list, time_ours(int_tris, false, out, buffer, pixels[2]));
    }
    const double px = double(set.pixels);
    const bool counts_exact = pixels[0] == set.pixels && pixels[1] == set.pixels && pixels[2] == set.pixels;
    std::printf("  %-6.0f %-7zu %-9zu %-10.3e %-10.3e %-10.3e %-10.3e %-8.2f %-8.2f %-8.2f%s\n", s.area, s.n, set.pixels, px / lp,
                px / int_fb, px / dbl_fb, px / int_list, lp / int_fb, lp / dbl_fb, lp / int_list,
                counts_exact ? "" : "  (pixel counts differ from exact!)");
  }
}

}  // namespace

int main(int argc, char** argv) {
  setenv("LP_NUM_THREADS", "1", 1);  // before the first context: llvmpipe reads it once
  const std::size_t triangles = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 100000;
  Llvmpipe gl;
  std::printf("renderer: %s\n\n", gl.renderer().c_str());

  // 1. The convention: the same hard cases, as given and mirrored in y.
  square_experiment(gl);
  const auto probe_cases = on_grid_cases(10000, 7);
  print_comparison("convention experiment, drawn as given (window = sample + (1/2, 1/2) + cell offset):",
                   compare(gl, probe_cases, false, 4));
  print_comparison("convention experiment, drawn mirrored in y and mirrored back:", compare(gl, probe_cases, true, 4));

  // 2. On llvmpipe's grid: goal 0.
  const auto t0 = std::chrono::steady_clock::now();
  const auto cases = on_grid_cases(triangles, 2026);
  const Comparison on_grid = compare(gl, cases, kMirror);
  print_comparison("\non the 1/256 grid, drawn as given (the documented mapping):", on_grid);
  std::printf("  (%.1f s, llvmpipe and oracle)\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  const Comparison straddling = compare(gl, cases, kMirror, 8, false, Layout{64, 32});
  print_comparison("the same, cells moved by 32 px so that cases straddle llvmpipe's 64-px tiles:", straddling);
  const auto t1 = std::chrono::steady_clock::now();
  const Comparison large = compare(gl, large_cases(triangles / 50, 2028), kMirror, 8, false, Layout{256, 0});
  print_comparison("large triangles (64 to 240 px, several tiles each), cells of 256 px:", large);
  std::printf("  (%.1f s)\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count());
  print_catalog(gl, cases, "triangle-edge");
  print_catalog(gl, cases, "triangle-dda");

  // 3. Off the grid: llvmpipe snaps each vertex to 1/256 (round to nearest, ties to even).
  const auto off_grid = off_grid_cases(triangles / 5, 2027);
  print_comparison("\noff the grid (1/4096), drawn as given:", compare(gl, off_grid, kMirror));
  print_comparison("off the grid, against the exact answer for the snapped vertices:", compare(gl, off_grid, kMirror, 8, true));

  // 4. Speed.
  fill_rate(gl);
  return on_grid.differing + straddling.differing + large.differing == 0 ? 0 : 1;
}
