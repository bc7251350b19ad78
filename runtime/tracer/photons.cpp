#include "tracer/photons.hpp"
#include <algorithm>
#include <cmath>
#include "tracer/parallel.hpp"
#include "tracer/photon_trace.hpp"

namespace sw::tracer {

namespace {

// 1/50 of the diagonal of the bounded objects' box (1 when there are none): the default gather radius.
double default_radius(const TraceScene<double>& ts) {
  Vec3<double> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  auto grow = [&](const Vec3<double>& p) {
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  };
  for (const Prim<double>& o : ts.objects) {
    const Vec3<double> r{o.radius, o.radius, o.radius};
    if (o.shape == Shape::sphere) grow(o.a - r), grow(o.a + r);
    if (o.shape == Shape::box) grow(o.a), grow(o.b);
    if (o.shape == Shape::triangle) grow(o.v[0]), grow(o.v[1]), grow(o.v[2]);
    if (o.shape == Shape::mesh)
      for (const auto& t : ts.meshes[static_cast<std::size_t>(o.mesh)].tris) grow(t[0]), grow(t[1]), grow(t[2]);
  }
  if (hi.x < lo.x) return 1;
  const Vec3<double> d = hi - lo;
  const double diag = std::sqrt(dot(d, d));
  return diag > 0 ? diag / 50 : 1;
}

}  // namespace

void build_photon_map(const Scene& s, const TraceScene<double>& ts, unsigned threads, PhotonMap& map, std::uint64_t& rays) {
  std::vector<std::size_t> emitters;
  for (std::size_t i = 0; i < ts.lights.size(); ++i)
    if (ts.lights[i].type != lighting::LightType::directional) emitters.push_back(i);
  if (emitters.empty() || s.photons.count == 0) return;
  constexpr std::int64_t kBlock = 4096;
  struct Block {
    std::size_t light;
    std::int64_t first, last, n;
    std::vector<Vec3<double>> at, power;
    std::uint64_t rays = 0;
  };
  std::vector<Block> blocks;
  const auto per = s.photons.count / static_cast<std::int64_t>(emitters.size());
  for (std::size_t e = 0; e < emitters.size(); ++e) {
    const std::int64_t n = per + (e == 0 ? s.photons.count % static_cast<std::int64_t>(emitters.size()) : 0);
    for (std::int64_t k = 0; k < n; k += kBlock) blocks.push_back({emitters[e], k, std::min(n, k + kBlock), n, {}, {}, 0});
  }
  parallel_rows(static_cast<std::int64_t>(blocks.size()), threads, {}, [&](std::int64_t b) {
    Block& x = blocks[static_cast<std::size_t>(b)];
    trace_photons(ts, x.light, x.first, x.last, x.n, s.photons.seed, x.at, x.power, x.rays);
  });
  for (Block& b : blocks) {
    map.at.insert(map.at.end(), b.at.begin(), b.at.end());
    map.power.insert(map.power.end(), b.power.begin(), b.power.end());
    rays += b.rays;
  }
  map.gather = s.photons.gather;
  map.radius = sgn(s.photons.radius.q) > 0 ? s.photons.radius.d : default_radius(ts);
  index_photons(map);
}

}  // namespace sw::tracer
