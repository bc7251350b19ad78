// Small vector types generic over the number type. GLM needs IEEE or integer scalars; these work
// for exact rationals too.
#pragma once
#include <cstdint>

namespace sw {

template <class T> struct Vec2 {
  T x{}, y{};
  T& operator[](int a) { return a == 0 ? x : y; }
  const T& operator[](int a) const { return a == 0 ? x : y; }
  friend Vec2 operator+(const Vec2& a, const Vec2& b) { return {T(a.x + b.x), T(a.y + b.y)}; }
  friend Vec2 operator-(const Vec2& a, const Vec2& b) { return {T(a.x - b.x), T(a.y - b.y)}; }
  friend Vec2 operator*(const T& s, const Vec2& a) { return {T(s * a.x), T(s * a.y)}; }
  friend bool operator==(const Vec2& a, const Vec2& b) { return a.x == b.x && a.y == b.y; }
};

template <class T> struct Vec3 {
  T x{}, y{}, z{};
  T& operator[](int a) { return a == 0 ? x : a == 1 ? y : z; }
  const T& operator[](int a) const { return a == 0 ? x : a == 1 ? y : z; }
  friend Vec3 operator+(const Vec3& a, const Vec3& b) { return {T(a.x + b.x), T(a.y + b.y), T(a.z + b.z)}; }
  friend Vec3 operator-(const Vec3& a, const Vec3& b) { return {T(a.x - b.x), T(a.y - b.y), T(a.z - b.z)}; }
  friend Vec3 operator*(const T& s, const Vec3& a) { return {T(s * a.x), T(s * a.y), T(s * a.z)}; }
  friend bool operator==(const Vec3& a, const Vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
};

template <class T> T dot(const Vec3<T>& a, const Vec3<T>& b) { return T(a.x * b.x + a.y * b.y + a.z * b.z); }
template <class T> Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {T(a.y * b.z - a.z * b.y), T(a.z * b.x - a.x * b.z), T(a.x * b.y - a.y * b.x)};
}

// A pixel or grid cell index. Pixel (i, j) is the half-open square [i-1/2, i+1/2) x [j-1/2, j+1/2).
struct Pixel {
  std::int64_t x = 0, y = 0;
  friend bool operator==(const Pixel&, const Pixel&) = default;
  friend auto operator<=>(const Pixel&, const Pixel&) = default;
};

}  // namespace sw
