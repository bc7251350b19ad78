// The pipeline family's oracle: brute-force exact answers from the geometry of the view volume, not
// from the algorithms' matrices. Window positions by similar triangles onto the near plane and
// depth as the hyperbola in 1/distance GL's depth follows; the view volume's inside by its
// bounds in eye space; culling by CGAL's exact plane-side tests against planes through the view
// volume's corners, and orientation predicates for facing and winding. A camera whose frame is
// irrational (reference mode's) has it to 400 bits; a rational one exactly.
#pragma once
#include <array>
#include <optional>
#include <vector>
#include "core/number.hpp"
#include "pipeline/camera.hpp"

namespace sw::pipeline_oracle {

using Camera = pipe::Camera<Rational>;

// The camera's unit frame: forward, right and up.
struct Frame {
  std::array<Rational, 3> fwd, right, up;
};
Frame frame(const Camera& cam);

struct Vertex {
  std::array<Rational, 3> world, eye;  // eye: along right, up and -forward from the eye
  std::array<Rational, 4> clip;
  bool inside = false;
  std::optional<std::array<Rational, 3>> ndc, win;  // none on or behind the eye's plane
  Rational distance;                                // along the view direction (eye space's -z)
};

// Precondition: M is affine (last row 0 0 0 1).
Vertex transform(const pipe::Mat4<Rational>& M, const Camera& cam, const std::array<Rational, 3>& p);

// A triangle's two facing tests. toward: the exact orientation of (a, b, c, eye) (in orthographic,
// of a moved toward the eye); winding: the orientation of the window positions, none when a vertex
// lies on or behind the eye's plane.
struct Facing {
  int toward = 0;
  std::optional<int> winding;
};
Facing facing(const Camera& cam, const std::array<std::array<Rational, 3>, 3>& tri);

// A volume against the view volume: outside a plane through the volume's corners, straddling one,
// or inside all six. A box is its eight corners (axis-aligned or not); a sphere its centre and
// radius, by exact squared distances.
enum class Cull { outside, straddles, inside };
// The view volume's corners, and its planes a.x + d = 0 through them (left, right, bottom, top,
// near, far), each with the volume on its positive side, at its own scale.
struct Plane {
  std::array<Rational, 3> a;
  Rational d;
};
std::array<std::array<Rational, 3>, 8> corners(const Camera& cam);
std::array<Plane, 6> planes(const Camera& cam);
Cull cull_sphere(const Camera& cam, const std::array<Rational, 3>& c, const Rational& r);
Cull cull_corners(const Camera& cam, const std::array<std::array<Rational, 3>, 8>& corners);

// The samples of a width x height window a window-space triangle covers: every sample of its box
// in the window tested by CGAL's orientation with the fill family's tie rule (a sample on an edge
// is covered on a left or bottom edge). None for a triangle of zero area.
std::vector<Pixel> window_samples(const std::array<std::array<Rational, 3>, 3>& v, std::int64_t width, std::int64_t height);

// The z-buffer by brute force: for each triangle in order, every sample of its box in the window
// is tested for cover (CGAL's orientation with the fill family's tie rule: a sample on an edge is
// covered on a left or bottom edge), its depth found from barycentric weights, offset by the slope
// of CGAL's plane through the vertices, quantized and tested.
struct DepthTriangle {
  std::array<std::array<Rational, 3>, 3> v;  // window x, y, depth
  std::int64_t id = 0;
  Rational factor, units;
};
struct DepthImage {
  std::vector<std::int64_t> ids;
  std::vector<Rational> depth;
  std::int64_t fragments = 0, passed = 0, ties = 0;
};
DepthImage z_buffer(std::int64_t width, std::int64_t height, const std::vector<DepthTriangle>& tris, int bits, bool lequal,
                    const Rational& clear);

// Blending by brute force, per pixel: the fragments of the triangles that cover it
// (window_samples), depth by the fill oracle's linear interpolation, in the order given, through
// GL_LESS and the over operator.
struct BlendTriangle {
  std::array<std::array<Rational, 3>, 3> v;
  std::array<Rational, 3> rgb;
  Rational alpha;
};
std::vector<std::array<Rational, 3>> blend(std::int64_t width, std::int64_t height, const std::vector<BlendTriangle>& tris,
                                           const std::vector<std::size_t>& order, const std::array<Rational, 3>& background,
                                           bool depth_write);

// GL's fog factor at distance c, clamped to [0, 1]: (end - c)/(end - start) exactly, or
// e^(-density c), e^(-(density c)^2) to 400 bits. mode: 0 linear, 1 exp, 2 exp2.
Rational fog_factor(int mode, const Rational& start, const Rational& end, const Rational& density, const Rational& c);

}  // namespace sw::pipeline_oracle
