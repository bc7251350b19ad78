// The BVH against its peers, one thread, plain main printing Markdown tables:
//  - queries: untraced double bvh-traverse (built once, then bvh_query per ray) against Embree 3's
//    rtcIntersect1 and CGAL's AABB_tree (Epick, first_intersection), on CGAL's real meshes (bunny,
//    armadillo, dragon, elephant: scripts/meshes.sh) and generated ones, with primary rays from a
//    camera framing the mesh and incoherent rays (random origins and directions). Every ray where
//    the three disagree, and a sample where they agree, is decided by the exact answer: the same
//    BVH structure traversed in exact rationals (its boxes bound the triangles exactly), itself
//    checked against the brute-force oracle on a few rays. kd-traverse (untraced double, over a
//    kd-build of the same mesh) runs on the same rays; its disagreements are decided the same way.
//  - builds: Mprims/s of bvh-build (and Embree's build, and kd-build) at 10^4, 10^5, 10^6
//    generated triangles, ns per N log2 N, bytes per primitive.
// Usage: bench_spatial_peers [mesh dir] (default $SW_MESH_DIR, else out/meshes).
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <list>
#include "spatial/bvh_cases.hpp"
#include "spatial/bvh_traverse.hpp"
#include "spatial/kd_build.hpp"
#include "spatial/kd_traverse.hpp"
#include "spatial/spatial_common.hpp"
#include "spatial_oracle.hpp"
#ifdef SW_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

using namespace sw;
using spatial::Mesh;
using spatial::RayIn;
using Tri = std::array<Vec3<double>, 3>;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::vector<Tri> tris_of(const Mesh& m) {
  std::vector<Tri> t;
  t.reserve(m.size());
  for (std::size_t i = 0; i < m.size(); ++i) t.push_back(m.triangle<double>(i));
  return t;
}

// Primary rays: a w x w pinhole camera at 2.2 radii from the mesh's centre, looking at it.
std::vector<RayIn> primary_rays(const Mesh& m, int w) {
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& v : m.v)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  std::array<double, 3> c, eye, f, r, u;
  double rad = 0;
  for (int k = 0; k < 3; ++k) c[k] = (lo[k] + hi[k]) / 2, rad += (hi[k] - lo[k]) * (hi[k] - lo[k]) / 4;
  rad = std::sqrt(rad);
  const std::array<double, 3> dir{0.4, 0.35, 0.85};
  for (int k = 0; k < 3; ++k) eye[k] = c[k] + 2.2 * rad * dir[k], f[k] = -dir[k];
  const std::array<double, 3> up{0, 1, 0};
  r = {f[1] * up[2] - f[2] * up[1], f[2] * up[0] - f[0] * up[2], f[0] * up[1] - f[1] * up[0]};
  const double rn = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  for (double& x : r) x /= rn;
  u = {r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]};
  const double s = std::tan(0.5 * 0.7);  // 40 degrees
  std::vector<RayIn> out;
  for (int j = 0; j < w; ++j)
    for (int i = 0; i < w; ++i) {
      const double x = (2 * (i + 0.5) / w - 1) * s, y = (1 - 2 * (j + 0.5) / w) * s;
      RayIn ray;
      ray.o = eye;
      for (int k = 0; k < 3; ++k) ray.d[k] = f[k] + x * r[k] + y * u[k];
      out.push_back(ray);
    }
  return out;
}

// Incoherent rays: origins uniform in the mesh's box (grown by 20%), directions uniform.
std::vector<RayIn> incoherent_rays(const Mesh& m, std::size_t n, std::uint64_t seed) {
  std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const auto& v : m.v)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  std::normal_distribution<double> g;
  std::vector<RayIn> out;
  for (std::size_t i = 0; i < n; ++i) {
    RayIn ray;
    for (int k = 0; k < 3; ++k) ray.o[k] = (lo[k] + hi[k]) / 2 + u(rng) * (hi[k] - lo[k]), ray.d[k] = g(rng);
    out.push_back(ray);
  }
  return out;
}

ray::Ray3<double> dray(const RayIn& r) { return {{r.o[0], r.o[1], r.o[2]}, {r.d[0], r.d[1], r.d[2]}}; }
ray::Ray3<Rational> qray(const RayIn& r) { return {spatial::vec_from<Rational, 3>(r.o), spatial::vec_from<Rational, 3>(r.d)}; }

// The same tree in exact rationals: double boxes are exact bounds of double vertices.
spatial::Bvh<Rational> exact_copy(const spatial::Bvh<double>& b) {
  spatial::Bvh<Rational> e;
  e.order = b.order, e.leaves = b.leaves, e.depth = b.depth;
  for (const auto& n : b.nodes) {
    spatial::BvhNode<Rational> q;
    for (int k = 0; k < 3; ++k) q.box.lo[k] = num::to_rational(n.box.lo[k]), q.box.hi[k] = num::to_rational(n.box.hi[k]);
    q.parent = n.parent, q.left = n.left, q.right = n.right, q.first = n.first, q.count = n.count, q.depth = n.depth, q.axis = n.axis;
    e.nodes.push_back(std::move(q));
  }
  return e;
}

#ifdef SW_HAVE_EMBREE
// Embree's scene over the mesh (float vertices), committed: what its build time is taken over.
RTCScene embree_scene(RTCDevice device, const Mesh& m) {
  RTCScene sc = rtcNewScene(device);
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), m.v.size()));
  for (std::size_t i = 0; i < m.v.size(); ++i)
    for (int k = 0; k < 3; ++k) v[3 * i + k] = float(m.v[i][k]);
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), m.f.size()));
  for (std::size_t i = 0; i < m.f.size(); ++i)
    for (int k = 0; k < 3; ++k) idx[3 * i + k] = static_cast<unsigned>(m.f[i][k]);
  rtcCommitGeometry(geom);
  rtcAttachGeometry(sc, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(sc);
  return sc;
}
#endif

// CGAL's AABB tree over Epick triangles.
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CTri = K::Triangle_3;
using CList = std::vector<CTri>;
using Prim = CGAL::AABB_triangle_primitive<K, CList::const_iterator>;
using CTree = CGAL::AABB_tree<CGAL::AABB_traits<K, Prim>>;

struct SetReport {
  std::string mesh, rays;
  std::size_t n_tris = 0, n_rays = 0;
  double ours = 0, embree = 0, cgal = 0, kd = 0;  // rays per second (kd: kd-traverse, double)
  std::size_t hits = 0;
  std::size_t dis_embree = 0, dis_cgal = 0, dis_kd = 0, decided = 0, kd_wrong = 0;
  // Who is right among those decided exactly: ours (double), Embree, CGAL wrong counts; ties:
  // another id hit at the same exact t (right up to the tie rule).
  std::size_t ours_wrong = 0, embree_wrong = 0, embree_tie = 0, cgal_wrong = 0, cgal_tie = 0, sample_ok = 0, sample = 0;
};

template <class F> double best_time(int reps, F&& f) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = Clock::now();
    f();
    best = std::min(best, seconds_since(t0));
  }
  return best;
}

SetReport run_set(const std::string& name, const Mesh& m, const std::vector<Tri>& tris, const spatial::Bvh<double>& bvh,
                  const spatial::KdTree<double, 3>& kd, const std::vector<oracle::Triangle3>& qtris, const spatial::Bvh<Rational>& qbvh, const std::string& kind,
                  const std::vector<RayIn>& rays, [[maybe_unused]] void* scene, const CTree& ctree, const CList& clist) {
  SetReport rep;
  rep.mesh = name, rep.rays = kind, rep.n_tris = m.size(), rep.n_rays = rays.size();
  NoProbe none;
  std::vector<std::int32_t> ours(rays.size()), emb(rays.size(), -2), cg(rays.size()), kds(rays.size());
  const spatial::BvhQuery<double> q;
  rep.ours = rays.size() / best_time(3, [&] {
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const auto h = spatial::bvh_query<double>(bvh, tris, dray(rays[i]), q, none);
      ours[i] = h.hit ? h.prim : -1;
    }
  });
  rep.kd = rays.size() / best_time(3, [&] {
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const auto h = spatial::kd_traverse_tree<double>(kd, tris, dray(rays[i]), none);
      kds[i] = h.hit ? h.prim : -1;
    }
  });
#ifdef SW_HAVE_EMBREE
  rep.embree = rays.size() / best_time(3, [&] {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      RTCRayHit rh{};
      rh.ray.org_x = float(rays[i].o[0]), rh.ray.org_y = float(rays[i].o[1]), rh.ray.org_z = float(rays[i].o[2]);
      rh.ray.dir_x = float(rays[i].d[0]), rh.ray.dir_y = float(rays[i].d[1]), rh.ray.dir_z = float(rays[i].d[2]);
      rh.ray.tnear = 0, rh.ray.tfar = std::numeric_limits<float>::infinity(), rh.ray.mask = ~0u;
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(static_cast<RTCScene>(scene), &ctx, &rh);
      emb[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1 : static_cast<std::int32_t>(rh.hit.primID);
    }
  });
#endif
  rep.cgal = rays.size() / best_time(1, [&] {
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const K::Ray_3 r(K::Point_3(rays[i].o[0], rays[i].o[1], rays[i].o[2]), K::Vector_3(rays[i].d[0], rays[i].d[1], rays[i].d[2]));
      const auto h = ctree.first_intersection(r);
      cg[i] = h ? static_cast<std::int32_t>(h->second - clist.begin()) : -1;
    }
  });
  // Exact decisions: every ray where the peers disagree with ours, and a sample where all agree.
  std::size_t sampled = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    rep.hits += ours[i] >= 0;
    const bool de = emb[i] != -2 && emb[i] != ours[i], dc = cg[i] != ours[i], dk = kds[i] != ours[i];
    rep.dis_embree += de, rep.dis_cgal += dc, rep.dis_kd += dk;
    const bool sample = !de && !dc && !dk && i % 97 == 0 && sampled < 400;
    if (!de && !dc && !dk && !sample) continue;
    if (rep.decided >= 40000) continue;  // a cap (printed as decided)
    sampled += sample;
    ++rep.decided;
    const auto r = qray(rays[i]);
    const auto ex = spatial::bvh_query<Rational>(qbvh, qtris, r, spatial::BvhQuery<Rational>{}, none);
    const std::int32_t want = ex.hit ? ex.prim : -1;
    auto tie = [&](std::int32_t p) {
      if (p < 0 || !ex.hit) return false;
      const auto h = oracle::ray_triangle(r.o, r.d, qtris[static_cast<std::size_t>(p)]);
      return h.hit && h.t == ex.t;
    };
    if (sample) ++rep.sample, rep.sample_ok += ours[i] == want;
    rep.ours_wrong += ours[i] != want;
    rep.kd_wrong += kds[i] != want;
    if (emb[i] != -2 && emb[i] != want) (tie(emb[i]) ? rep.embree_tie : rep.embree_wrong)++;
    if (cg[i] != want) (tie(cg[i]) ? rep.cgal_tie : rep.cgal_wrong)++;
  }
  return rep;
}

// The exact BVH traversal against the brute-force oracle on a few rays (it is the classifier).
std::size_t check_classifier(const Mesh& m, const std::vector<oracle::Triangle3>& qtris, const spatial::Bvh<Rational>& qbvh, const std::vector<RayIn>& rays) {
  NoProbe none;
  std::size_t bad = 0;
  for (std::size_t i = 0; i < rays.size(); i += rays.size() / 3) {
    const auto ex = spatial::bvh_query<Rational>(qbvh, qtris, qray(rays[i]), spatial::BvhQuery<Rational>{}, none);
    const auto want = spatial::closest_hit_oracle(m, rays[i]);
    bad += ex.hit != want.hit || (ex.hit && (ex.prim != want.prim || ex.t != want.exact->t));
  }
  return bad;
}

// The SAH cost as bvh-build reports it: inner nodes 2 A(node)/A(root), leaves n A(leaf)/A(root).
double sah_cost(const spatial::Bvh<double>& b) {
  const double root = b.nodes[0].box.half_area();
  double c = 0;
  for (const auto& n : b.nodes) c += (n.left < 0 ? n.count : spatial::kBvhTraversalCost) * n.box.half_area() / root;
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  const char* env = std::getenv("SW_MESH_DIR");
  const std::string dir = argc > 1 ? argv[1] : env ? env : "out/meshes";
  std::vector<std::pair<std::string, Mesh>> meshes;
  for (const char* f : {"bunny00.off", "armadillo.off", "ChineseDragon-10kv.off", "elephant.off"}) {
    const auto path = std::filesystem::path(dir) / f;
    if (!std::filesystem::exists(path)) {
      std::fprintf(stderr, "%s missing: run scripts/meshes.sh (skipped)\n", path.c_str());
      continue;
    }
    meshes.emplace_back(f, spatial::read_mesh_file(path.string()));
  }
  std::mt19937_64 rng(20261123);
  meshes.emplace_back("random soup 10^5", spatial::cases::random_mesh(rng, 100000, 0.05));
  meshes.emplace_back("height grid 256^2", spatial::cases::grid_mesh(256, 256, false, 3));
#ifdef SW_HAVE_EMBREE
  RTCDevice device = rtcNewDevice("threads=1");
#endif
  std::vector<SetReport> reports;
  std::printf("| mesh | triangles | our build ms | nodes | leaves | depth | SAH cost | classifier vs brute force (3 rays) |\n|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> build_rows;
  for (const auto& [name, m] : meshes) {
    const auto tris = tris_of(m);
    NoProbe none;
    spatial::Bvh<double> bvh;
    const double tb = best_time(1, [&] { bvh = spatial::bvh_build<double>(tris, none); });
    std::vector<oracle::Triangle3> qtris;
    qtris.reserve(m.size());
    for (std::size_t i = 0; i < m.size(); ++i) qtris.push_back(m.triangle<Rational>(i));
    const auto qbvh = exact_copy(bvh);
    std::vector<spatial::Box<double, 3>> boxes;
    for (const auto& tr : tris) boxes.push_back(spatial::triangle_bounds(tr));
    const spatial::KdTree<double, 3> kd = spatial::kd_build<double, 3>(boxes, false, none);
    void* scene = nullptr;
#ifdef SW_HAVE_EMBREE
    RTCScene sc = embree_scene(device, m);
    scene = sc;
#endif
    CList clist;
    for (const auto& f : m.f) {
      auto p = [&](int c) { return K::Point_3(m.v[f[c]][0], m.v[f[c]][1], m.v[f[c]][2]); };
      clist.emplace_back(p(0), p(1), p(2));
    }
    // CGAL's primitives must not be degenerate (its precondition); ours take them (never hit).
    CTree ctree;
    for (auto it = clist.cbegin(); it != clist.cend(); ++it)
      if (!it->is_degenerate()) ctree.insert(Prim(it));
    ctree.build();
    const auto prim = primary_rays(m, 256), inco = incoherent_rays(m, 65536, 7);
    std::printf("| %s | %zu | %.1f | %zu | %zu | %zu | %.2f | %zu wrong |\n", name.c_str(), m.size(), tb * 1e3, bvh.nodes.size(), bvh.leaves, bvh.depth, sah_cost(bvh),
                check_classifier(m, qtris, qbvh, inco));
    reports.push_back(run_set(name, m, tris, bvh, kd, qtris, qbvh, "primary 256^2", prim, scene, ctree, clist));
    reports.push_back(run_set(name, m, tris, bvh, kd, qtris, qbvh, "incoherent", inco, scene, ctree, clist));
    if (name.rfind("height grid", 0) == 0) {
      std::vector<RayIn> edge;
      std::mt19937_64 r2(11);
      for (int i = 0; i < 65536; ++i) edge.push_back(spatial::cases::grid_ray(m, 256, 256, r2, i % 3));
      reports.push_back(run_set(name, m, tris, bvh, kd, qtris, qbvh, "through edges/vertices", edge, scene, ctree, clist));
    }
#ifdef SW_HAVE_EMBREE
    rtcReleaseScene(sc);
#endif
    std::fflush(stdout);
  }
  std::printf("\n| mesh | rays | n | hit | ours Mrays/s | Embree Mrays/s | ours/Embree | CGAL Mrays/s | ours != Embree | ours != CGAL | decided exactly | ours wrong | Embree wrong (+ties) | CGAL wrong (+ties) | agreeing sample ours right |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& r : reports)
    std::printf("| %s | %s | %zu | %zu | %.3f | %.3f | %.2f | %.3f | %zu | %zu | %zu | %zu | %zu (+%zu) | %zu (+%zu) | %zu/%zu |\n", r.mesh.c_str(), r.rays.c_str(), r.n_rays, r.hits, r.ours / 1e6,
                r.embree / 1e6, r.embree > 0 ? r.ours / r.embree : 0.0, r.cgal / 1e6, r.dis_embree, r.dis_cgal, r.decided, r.ours_wrong, r.embree_wrong, r.embree_tie, r.cgal_wrong, r.cgal_tie,
                r.sample_ok, r.sample);
  // kd-traverse (untraced double, over a kd-build of the same mesh) on the same rays.
  std::printf("\n| mesh | rays | kd-traverse Mrays/s | kd/Embree | kd/bvh-traverse | kd != bvh-traverse | kd wrong (decided exactly) |\n|---|---|---|---|---|---|---|\n");
  for (const auto& r : reports)
    std::printf("| %s | %s | %.3f | %.2f | %.2f | %zu | %zu |\n", r.mesh.c_str(), r.rays.c_str(), r.kd / 1e6, r.embree > 0 ? r.kd / r.embree : 0.0, r.kd / r.ours, r.dis_kd, r.kd_wrong);
  // Builds of generated soups: ours, Embree's (1 thread) and kd-build's.
  std::printf("\n| N | bvh-build Mprims/s | ns per N log2 N | bytes/prim | nodes | depth | Embree build Mprims/s | kd-build Mprims/s |\n|---|---|---|---|---|---|---|---|\n");
  for (const std::size_t n : {std::size_t{10000}, std::size_t{100000}, std::size_t{1000000}}) {
    std::mt19937_64 g(n);
    const Mesh m = spatial::cases::random_mesh(g, n, 0.2 * std::cbrt(1e4 / double(n)));
    const auto tris = tris_of(m);
    NoProbe none;
    spatial::Bvh<double> bvh;
    const double t = best_time(n >= 1000000 ? 1 : 3, [&] { bvh = spatial::bvh_build<double>(tris, none); });
    const double bytes = double(bvh.nodes.size() * sizeof(spatial::BvhNode<double>) + bvh.order.size() * 4) / double(n);
    double te = 0, tk = 0;
#ifdef SW_HAVE_EMBREE
    te = best_time(1, [&] { rtcReleaseScene(embree_scene(device, m)); });
#endif
    {
      std::vector<spatial::Box<double, 3>> boxes;
      for (const auto& tr : tris) boxes.push_back(spatial::triangle_bounds(tr));
      tk = best_time(1, [&] { (void)spatial::kd_build<double, 3>(boxes, false, none); });
    }
    std::printf("| %zu | %.2f | %.1f | %.1f | %zu | %zu | %.2f | %.2f |\n", n, n / t / 1e6, t * 1e9 / (double(n) * std::log2(double(n))), bytes, bvh.nodes.size(), bvh.depth,
                te > 0 ? n / te / 1e6 : 0.0, n / tk / 1e6);
    std::fflush(stdout);
  }
#ifdef SW_HAVE_EMBREE
  rtcReleaseDevice(device);
#endif
  return 0;
}
