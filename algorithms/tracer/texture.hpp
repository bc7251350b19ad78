// Textures: a checker and an image on the hit's (u, v); marble and wood evaluated at the hit point
// in space from seeded gradient noise (Perlin's improved noise, its permutation shuffled from the
// seed, so a render is reproducible); and a bump map that tilts the normal by the noise's
// gradient. Definitions: docs/tracer/scene-format.md#textures.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <vector>
#include "core/vec.hpp"

namespace sw::tracer {

inline std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

class Noise {
 public:
  explicit Noise(std::uint32_t seed = 0) {
    std::array<std::uint8_t, 256> p;
    std::iota(p.begin(), p.end(), std::uint8_t{0});
    std::uint64_t state = seed;
    for (int i = 255; i > 0; --i)
      std::swap(p[static_cast<std::size_t>(i)], p[splitmix64(state) % static_cast<std::uint64_t>(i + 1)]);
    for (std::size_t i = 0; i < 512; ++i) perm_[i] = p[i & 255];
  }
  // In [-1, 1] roughly; 0 at integer points.
  double at(double x, double y, double z) const {
    const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const int X = static_cast<int>(static_cast<std::int64_t>(fx) & 255),
              Y = static_cast<int>(static_cast<std::int64_t>(fy) & 255),
              Z = static_cast<int>(static_cast<std::int64_t>(fz) & 255);
    x -= fx, y -= fy, z -= fz;
    const double u = fade(x), v = fade(y), w = fade(z);
    auto h = [&](int i) { return static_cast<int>(perm_[static_cast<std::size_t>(i)]); };
    const int A = h(X) + Y, AA = h(A) + Z, AB = h(A + 1) + Z, B = h(X + 1) + Y, BA = h(B) + Z, BB = h(B + 1) + Z;
    return lerp(w,
                lerp(v, lerp(u, grad(h(AA), x, y, z), grad(h(BA), x - 1, y, z)),
                     lerp(u, grad(h(AB), x, y - 1, z), grad(h(BB), x - 1, y - 1, z))),
                lerp(v, lerp(u, grad(h(AA + 1), x, y, z - 1), grad(h(BA + 1), x - 1, y, z - 1)),
                     lerp(u, grad(h(AB + 1), x, y - 1, z - 1), grad(h(BB + 1), x - 1, y - 1, z - 1))));
  }
  // Four octaves of |noise|: the classic turbulence.
  double turbulence(double x, double y, double z) const {
    double t = 0, f = 1;
    for (int i = 0; i < 4; ++i, f *= 2) t += std::abs(at(x * f, y * f, z * f)) / f;
    return t;
  }
  // The gradient by central differences (h = 1e-3 in noise space).
  Vec3<double> gradient(double x, double y, double z) const {
    const double h = 1e-3;
    return {(at(x + h, y, z) - at(x - h, y, z)) / (2 * h), (at(x, y + h, z) - at(x, y - h, z)) / (2 * h),
            (at(x, y, z + h) - at(x, y, z - h)) / (2 * h)};
  }

 private:
  static double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }
  static double lerp(double t, double a, double b) { return a + t * (b - a); }
  static double grad(int hash, double x, double y, double z) {
    const int h = hash & 15;
    const double u = h < 8 ? x : y, v = h < 4 ? y : (h == 12 || h == 14) ? x : z;
    return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
  }
  std::array<std::uint8_t, 512> perm_{};
};

enum class TextureKind : std::uint8_t { checker, image, marble, wood };

struct TraceTexture {
  TextureKind kind = TextureKind::checker;
  double scale = 1;
  std::array<Vec3<double>, 2> colours{};
  Noise noise;
  std::shared_ptr<const std::vector<std::uint8_t>> rgb;  // image: 8-bit RGB, row 0 at the top (shared by every use of one file)
  std::int64_t width = 0, height = 0;
};

inline Vec3<double> mix(const Vec3<double>& a, const Vec3<double>& b, double t) { return a + t * Vec3<double>(b - a); }

// The texture's colour at (u, v) or at the point p.
inline Vec3<double> texture_colour(const TraceTexture& t, double u, double v, const Vec3<double>& p) {
  switch (t.kind) {
    case TextureKind::checker: {
      const auto parity =
          (static_cast<std::int64_t>(std::floor(u * t.scale)) + static_cast<std::int64_t>(std::floor(v * t.scale))) & 1;
      return t.colours[static_cast<std::size_t>(parity)];
    }
    case TextureKind::image: {
      const double fu = u - std::floor(u), fv = v - std::floor(v);  // repeats; v up, row 0 at the top
      const auto x = std::min<std::int64_t>(t.width - 1, static_cast<std::int64_t>(fu * double(t.width)));
      const auto y = std::min<std::int64_t>(t.height - 1, static_cast<std::int64_t>((1 - fv) * double(t.height)));
      const std::uint8_t* c = t.rgb->data() + 3 * static_cast<std::size_t>(y * t.width + x);
      return {c[0] / 255.0, c[1] / 255.0, c[2] / 255.0};
    }
    case TextureKind::marble: {
      const Vec3<double> q = t.scale * p;
      const double s = 0.5 + 0.5 * std::sin(6.283185307179586 * (q.x + 2 * t.noise.turbulence(q.x, q.y, q.z)));
      return mix(t.colours[0], t.colours[1], s);
    }
    case TextureKind::wood: {
      const Vec3<double> q = t.scale * p;
      const double r = std::sqrt(q.x * q.x + q.z * q.z) + 0.5 * t.noise.at(q.x, q.y, q.z);
      return mix(t.colours[0], t.colours[1], r - std::floor(r));
    }
  }
  return {};
}

struct TraceBump {
  bool on = false;
  double amplitude = 0, scale = 1;
  Noise noise;
};

// The normal n (unit) tilted by the tangential part of the noise gradient at scale p.
inline Vec3<double> bumped(const TraceBump& b, const Vec3<double>& n, const Vec3<double>& p) {
  const Vec3<double> q = b.scale * p;
  const Vec3<double> g = b.noise.gradient(q.x, q.y, q.z);
  const Vec3<double> tangential = g - dot(g, n) * n;
  const Vec3<double> m = n - b.amplitude * tangential;
  return (1 / std::sqrt(dot(m, m))) * m;
}

}  // namespace sw::tracer
