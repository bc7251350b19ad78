// The ray tracer's scene: camera, objects, materials (a lighting-family model plus mirror and
// glass), textures, lights and the render settings, read from JSON and validated as a whole
// before any work. The format, every key, its bounds and default: docs/tracer/scene-format.md.
// Geometry is kept exactly (Rational, as the rays family parses it) beside its double value, so
// that exact predicates can run later on the numbers as written.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include "input.hpp"
#include "lighting/lights.hpp"
#include "lighting/shade.hpp"
#include "rays/camera_ray.hpp"
#include "spatial/spatial_common.hpp"
#include "tracer/texture.hpp"
#include "tracer/trace_scene.hpp"

namespace sw::tracer {

// The documented bounds (docs/tracer/scene-format.md#bounds).
inline constexpr double kCoordBound = 1e15;  // the rays family's bound on any coordinate
inline constexpr std::size_t kMaxObjects = std::size_t{1} << 16;
inline constexpr std::size_t kMaxSceneTriangles = std::size_t{1} << 20;  // mesh triangles, all instances
inline constexpr std::size_t kMaxMaterials = 1024, kMaxTextures = 256;
inline constexpr std::size_t kMaxLights = 8;  // the lighting family's `shade` bound
inline constexpr std::int64_t kMaxResolution = 8192, kMaxDepth = 16, kMaxSamplesPerAxis = 16;
inline constexpr std::int64_t kMaxRaysPerPixel = std::int64_t{1} << 20;
inline constexpr std::int64_t kMaxImageSide = 16384;  // a PNG texture's width and height
// A PNG texture's texels: 48 MB as 8-bit RGB, decoded once per render.
inline constexpr std::int64_t kMaxImageTexels = std::int64_t{1} << 24;
// Photons emitted: the map of 2^20 costs about 3 s and 520 MB on one core (glass-spheres, measured).
inline constexpr std::int64_t kMaxPhotons = std::int64_t{1} << 20;
// A rendered image's pixels (each side at most kMaxResolution): 450 MB of colours at the bound.
inline constexpr std::int64_t kMaxPixels = std::int64_t{1} << 24;

// A number as written (exact) and its nearest double.
struct Real {
  Rational q;
  double d = 0;
};
struct Real3 {
  Vec3<Rational> q;
  std::array<double, 3> d{};
};

struct Camera {
  Real3 eye, vpn, vup;  // vpn points from the scene to the eye, as in camera-ray
  Real dist;            // the view plane's distance d > 0
  bool has_window = false;
  Real fov;                   // degrees, when !has_window
  std::array<Real, 4> window; // umin, umax, vmin, vmax on the view plane, when has_window (perspective only)
  ray::Projection projection = ray::Projection::perspective;
  std::int64_t width = 1, height = 1;
};

using ObjectKind = Shape;  // the renderer's object kinds (tracer/trace_scene.hpp)
std::string_view kind_name(ObjectKind k);

struct Object {
  ObjectKind kind = ObjectKind::sphere;
  int material = 0;          // index into Scene::materials
  Real3 a, b;                // sphere: a = centre; plane: a = point, b = normal; box: a = min, b = max
  Real radius;               // sphere
  std::array<Real3, 3> v;    // triangle, counter-clockwise seen from its front
  int mesh = -1;             // mesh: index into Scene::meshes
  Real scale;                // mesh: world = scale * file + translate
  Real3 translate;
};

// A mesh file, read once however many objects use it. mesh is null when files were not loaded.
struct MeshFile {
  std::string file;  // as written in the scene
  std::string path;  // resolved against the scene's directory
  std::shared_ptr<const spatial::Mesh> mesh;
  std::size_t first_object = 0;  // the first object naming it (errors point there)
};

std::string_view kind_name(TextureKind k);

struct Texture {
  std::string name;
  TextureKind kind = TextureKind::checker;
  Real scale;                      // checker: squares per unit of u and v; marble, wood: features per unit length
  std::array<Real3, 2> colours;    // checker, marble, wood
  std::uint32_t seed = 0;          // marble, wood
  std::string file, path;          // image: as written, and resolved
  std::int64_t image_width = 0, image_height = 0;  // image, when files were loaded
};

struct Bump {
  bool on = false;
  Real amplitude, scale;
  std::uint32_t seed = 0;
};

struct Material {
  std::string name;
  lighting::Material<Rational> shading;  // the `shade` model (convention "models")
  Real kr, kt, ior;                      // mirror and transmission weights, index of refraction
  int texture = -1;                      // index into Scene::textures, -1 for none
  Bump bump;
};

enum class SamplingKind : std::uint8_t { one, regular, jittered, adaptive };
std::string_view kind_name(SamplingKind k);
struct Sampling {
  SamplingKind kind = SamplingKind::one;
  std::int64_t n = 1;          // regular, jittered: n x n samples; adaptive: at most n x n (max_n)
  std::uint32_t seed = 0;      // jittered
  Real threshold;              // adaptive: refine while neighbouring samples differ by more
  std::int64_t samples() const { return n * n; }  // the most primary rays per pixel
};

// Caustic photons (docs/tracer/renderer.md#caustics); radius 0: derived from the scene at render.
struct Photons {
  std::int64_t count = 100000, gather = 64;
  Real radius;
  std::uint32_t seed = 0;
};

struct Scene {
  std::string description;
  Camera camera;
  std::vector<Object> objects;
  std::vector<MeshFile> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<lighting::Light<Rational>> lights;
  Real3 background, ambient;
  std::int64_t max_depth = 5;
  Sampling sampling;
  std::int64_t rays_per_pixel = 1024;
  Photons photons;
  std::size_t mesh_triangles = 0;  // over all mesh objects (0 when files were not loaded)
};

struct SceneOptions {
  std::string base_dir = ".";  // mesh and image paths are relative to it
  bool load_files = true;      // false: paths are checked as text only (the fuzz harness)
};

// Parses and validates a scene; every failure is one InputError line naming the JSON path
// ("scene.objects[2].radius: must be > 0").
Scene parse_scene(const Json& j, const SceneOptions& opt);
// Reads a scene file (within the readers' bounds); its paths are relative to its directory.
Scene read_scene_file(const std::string& path);

// The summary `stepwise scene check` prints: as JSON, and as lines of text.
Json scene_summary(const Scene& s);
std::string scene_summary_text(const Scene& s);

}  // namespace sw::tracer
