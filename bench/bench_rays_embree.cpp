// Peer comparison with Embree 3: a tessellated mesh of 10368 triangles and >= 10^5 rays aimed at
// its shared edges and vertices. Our closest hit is a brute force over the triangles of the
// blocks the ray passes (watertight, float), and every disagreement with Embree is classified with
// the exact oracle. Prints the classification, then times both with Google Benchmark.
#include <benchmark/benchmark.h>
#include <cmath>
#include <cstdio>
#include <limits>
#include "rays/cases.hpp"
#include "rays/ray_box.hpp"
#include "rays/ray_triangle_mt.hpp"
#include "rays/ray_triangle_watertight.hpp"
#ifdef SW_HAVE_EMBREE
#include <embree3/rtcore.h>
#include "rays_oracle.hpp"
#endif

using namespace sw;

namespace {

constexpr int kN = 72;        // 2 * 72^2 = 10368 triangles
constexpr int kPerEdge = 7;   // rays per shared edge: ~1.1e5 rays in all
constexpr int kBlock = 8;     // culling blocks of 8 x 8 cells

struct Mesh {
  rays::Grid grid = rays::make_grid(kN, 2026);
  std::vector<rays::FRay> rays = rays::grid_rays(grid, kPerEdge, 2027);
  struct Block { Vec3<float> lo, hi; int i0, j0; };
  std::vector<Block> blocks;
  Mesh() {
    for (int bj = 0; bj < kN; bj += kBlock)
      for (int bi = 0; bi < kN; bi += kBlock) {
        Block b{{1e30f, 1e30f, 1e30f}, {-1e30f, -1e30f, -1e30f}, bi, bj};
        for (int j = bj; j <= std::min(bj + kBlock, kN); ++j)
          for (int i = bi; i <= std::min(bi + kBlock, kN); ++i)
            for (int a = 0; a < 3; ++a) {
              const float v = grid.verts[j * (kN + 1) + i][a];
              b.lo[a] = std::min(b.lo[a], v), b.hi[a] = std::max(b.hi[a], v);
            }
        for (int a = 0; a < 3; ++a) b.lo[a] -= 1e-3f, b.hi[a] += 1e-3f;  // conservative culling
        blocks.push_back(b);
      }
  }
};
const Mesh& mesh() {
  static const Mesh m;
  return m;
}

struct Hit {
  int prim = -1;
  float t = std::numeric_limits<float>::infinity();
};

// Closest hit by brute force over the triangles of every block whose box the ray meets.
template <bool Watertight> Hit brute_force(const rays::FRay& r) {
  const Mesh& m = mesh();
  NoProbe none;
  const ray::Ray3<float> ray{{r.o[0], r.o[1], r.o[2]}, {r.d[0], r.d[1], r.d[2]}};
  Hit best;
  for (const auto& b : m.blocks) {
    if (!ray::ray_box<float>(ray, b.lo, b.hi, none).hit) continue;
    for (int j = b.j0; j < std::min(b.j0 + kBlock, kN); ++j)
      for (int i = b.i0; i < std::min(b.i0 + kBlock, kN); ++i)
        for (int k = 0; k < 2; ++k) {
          const int t = 2 * (j * kN + i) + k;
          const auto tri = m.grid.triangle(t);
          const std::array<Vec3<float>, 3> v{Vec3<float>{tri[0][0], tri[0][1], tri[0][2]}, Vec3<float>{tri[1][0], tri[1][1], tri[1][2]},
                                             Vec3<float>{tri[2][0], tri[2][1], tri[2][2]}};
          const auto h = Watertight ? ray::ray_triangle_watertight<float>(ray, v, none) : ray::ray_triangle_mt<float>(ray, v, none);
          if (h.hit && (h.t < best.t || (h.t == best.t && t < best.prim))) best = {t, h.t};
        }
  }
  return best;
}

#ifdef SW_HAVE_EMBREE
struct Embree {
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = nullptr;
  explicit Embree(bool robust) {
    const Mesh& m = mesh();
    scene = rtcNewScene(device);
    if (robust) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), m.grid.verts.size()));
    for (std::size_t i = 0; i < m.grid.verts.size(); ++i)
      for (int a = 0; a < 3; ++a) v[3 * i + a] = m.grid.verts[i][a];
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), m.grid.tris.size()));
    for (std::size_t i = 0; i < m.grid.tris.size(); ++i)
      for (int a = 0; a < 3; ++a) idx[3 * i + a] = unsigned(m.grid.tris[i][a]);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);
  }
  ~Embree() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
  Hit trace(const rays::FRay& r) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh{};
    rh.ray.org_x = r.o[0], rh.ray.org_y = r.o[1], rh.ray.org_z = r.o[2];
    rh.ray.dir_x = r.d[0], rh.ray.dir_y = r.d[1], rh.ray.dir_z = r.d[2];
    rh.ray.tnear = 0, rh.ray.tfar = std::numeric_limits<float>::infinity(), rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &ctx, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
    return {int(rh.hit.primID), rh.ray.tfar};
  }
};

Vec3<Rational> rq(const rays::F3& a) { return {a[0], a[1], a[2]}; }
oracle::RayResult exact_hit(const rays::FRay& r, int prim) {
  const auto tri = mesh().grid.triangle(prim);
  return oracle::ray_triangle(rq(r.o), rq(r.d), {rq(tri[0]), rq(tri[1]), rq(tri[2])});
}
// The exact closest hit among the triangles of the cells around the aim point (a ray aimed at an
// edge or vertex of this gently bent height field meets the mesh there first).
oracle::RayResult exact_closest(const rays::FRay& r, int* prim) {
  oracle::RayResult best;
  *prim = -1;
  for (int cj = std::max(r.cj - 2, 0); cj <= std::min(r.cj + 2, kN - 1); ++cj)
    for (int ci = std::max(r.ci - 2, 0); ci <= std::min(r.ci + 2, kN - 1); ++ci)
      for (int k = 0; k < 2; ++k) {
        const int t = 2 * (cj * kN + ci) + k;
        const auto h = exact_hit(r, t);
        if (h.hit && (!best.hit || h.t < best.t)) best = h, *prim = t;
      }
  return best;
}

// Classifies every disagreement between our closest hit and Embree's with the exact oracle.
void classify(const char* name, const Embree& e, bool watertight) {
  const Mesh& m = mesh();
  std::size_t agree = 0, tie = 0, ours_right = 0, embree_right = 0, both_wrong = 0, ours_miss = 0, embree_miss = 0;
  for (const auto& r : m.rays) {
    const Hit a = watertight ? brute_force<true>(r) : brute_force<false>(r), b = e.trace(r);
    if (a.prim == b.prim) { ++agree; continue; }
    int best_prim;
    const oracle::RayResult best = exact_closest(r, &best_prim);
    if (a.prim < 0 || b.prim < 0) {
      // One side missed; the exact ray hits the mesh (checked), so the misser is wrong.
      if (!best.hit) { ++both_wrong; continue; }
      (a.prim < 0 ? ours_miss : embree_miss)++;
      continue;
    }
    const auto ha = exact_hit(r, a.prim), hb = exact_hit(r, b.prim);
    const bool a_ok = ha.hit && ha.t == best.t, b_ok = hb.hit && hb.t == best.t;
    if (a_ok && b_ok) ++tie;            // both on the closest point: a shared edge or vertex
    else if (a_ok) ++ours_right;
    else if (b_ok) ++embree_right;
    else ++both_wrong;
  }
  std::printf("%-34s rays %zu: same triangle %zu; different triangle: exact tie (shared edge/vertex, both right) %zu, "
              "ours right %zu, Embree right %zu, neither closest %zu; ours missed %zu, Embree missed %zu\n",
              name, m.rays.size(), agree, tie, ours_right, embree_right, both_wrong, ours_miss, embree_miss);
}

void BM_embree(benchmark::State& s) {
  static const Embree e(s.range(0) != 0);
  std::size_t i = 0;
  for (auto _ : s) benchmark::DoNotOptimize(e.trace(mesh().rays[i++ % mesh().rays.size()]));
}
BENCHMARK(BM_embree)->Arg(0)->Arg(1);
#endif

void BM_brute_force_watertight(benchmark::State& s) {
  std::size_t i = 0;
  for (auto _ : s) benchmark::DoNotOptimize(brute_force<true>(mesh().rays[i++ % mesh().rays.size()]));
}
BENCHMARK(BM_brute_force_watertight);

}  // namespace

int main(int argc, char** argv) {
  std::printf("mesh: %zu triangles, %zu rays aimed at shared edges and vertices\n", mesh().grid.tris.size(), mesh().rays.size());
  std::size_t wt_miss = 0, mt_miss = 0;
  for (const auto& r : mesh().rays) wt_miss += brute_force<true>(r).prim < 0, mt_miss += brute_force<false>(r).prim < 0;
  std::printf("rays with no hit at all (float): watertight %zu, Moller-Trumbore %zu\n", wt_miss, mt_miss);
#ifdef SW_HAVE_EMBREE
  {
    const Embree plain(false), robust(true);
    classify("watertight(float) vs Embree", plain, true);
    classify("watertight(float) vs Embree ROBUST", robust, true);
    classify("Moller-Trumbore(float) vs Embree", plain, false);
  }
#else
  std::printf("Embree 3 not found at configure time: peer comparison skipped\n");
#endif
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
