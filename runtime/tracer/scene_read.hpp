// The scene reader's shared pieces (scene.cpp, scene_parts.cpp): typed readers that name the JSON
// path in every error. Internal to runtime/tracer.
#pragma once
#include <concepts>
#include <string>
#include "tracer/scene.hpp"

namespace sw::tracer::detail {

std::string at(const std::string& what, const char* key);  // what + "." + key
template <std::integral I> std::string at(const std::string& what, I i) { return what + "[" + std::to_string(i) + "]"; }
// A number in [lo, hi]; open_lo makes the lower end exclusive ("must be > lo").
Real real(const Json& j, const std::string& what, double lo, double hi, bool open_lo = false);
Real real_or(const Json& obj, const char* key, const std::string& what, double lo, double hi, Real dflt, bool open_lo = false);
Real real_of(const Rational& q);
// [x, y, z] within kCoordBound; nonzero refuses the zero vector.
Real3 point(const Json& j, const std::string& what);
Real3 nonzero(const Json& j, const std::string& what);
Real3 colour(const Json& j, const std::string& what);  // [r, g, b], each in [0, 1e6]
Real3 colour_or(const Json& obj, const char* key, const std::string& what, const Real3& dflt);
Real3 real3_of(const Vec3<Rational>& q);
std::uint32_t seed_or(const Json& obj, const char* key, const std::string& what);
// A string value (of at most 4096 bytes, no NUL).
std::string text(const Json& j, const std::string& what);
// A relative file path resolved against base; with load, the file must exist and be readable.
std::string resolve(const std::string& file, const std::string& what, const SceneOptions& opt);
// Names of materials and textures: 1 to 64 letters, digits, '-', '_' or '.'.
void check_name(const std::string& name, const std::string& what);

std::vector<Texture> parse_textures(const Json& j, const std::string& what, const SceneOptions& opt);
std::vector<Material> parse_materials(const Json& j, const std::string& what, const std::vector<Texture>& textures);
std::vector<lighting::Light<Rational>> parse_lights(const Json& j, const std::string& what);
Sampling parse_sampling(const Json& j, const std::string& what);

}  // namespace sw::tracer::detail
