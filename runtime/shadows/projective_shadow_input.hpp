// projective-shadow's input, parsed once: the rasterized scene, one light, the receiver (a plane or
// a triangle object) and its plane oriented toward the light, the depth test, the offset and the
// stencil; the points the eye sees with their exact visibility (shadow-map's, map_input). The oracle
// is the closed form: the eye's ray meets the receiver's plane at Q; Q is covered when the segment
// from Q to the light crosses an occluder's triangle, and the fragment there passes by its exact
// depth and offset against the seen point's. JSON:
// {"scene": ..., "size": [w, h], "stacks": n, "light": i, "receiver": k, "depth": "less" | "lequal",
//  "offset": [factor, units], "stencil": true}
// Semantics: docs/shadows/semantics.md#projective-shadow.
#pragma once
#include <memory>
#include <vector>
#include "shadows/projective_shadow.hpp"
#include "shadows/shadow_map_input.hpp"

namespace sw::shadowspec {

struct ProjectiveInput {
  std::shared_ptr<const MapInput> seen;
  std::int32_t receiver = 0;
  pipe::Vec4<Rational> plane, light;  // P . L > 0
  shadow::ProjectiveParams<Rational> params;
};
struct ProjectiveInputRef {
  std::shared_ptr<const ProjectiveInput> p;
};
ProjectiveInputRef parse_projective_input(const Json& j);
// The receiver (-1: the first plane or triangle object) and its plane, oriented so that P . L > 0;
// throws InputError ("receiver: ...") for another object or a light in the plane.
struct ReceiverPlane {
  std::int32_t receiver = 0;
  pipe::Vec4<Rational> plane, light;
};
ReceiverPlane receiver_plane(const RasterScene& s, std::size_t light, std::int64_t receiver);
std::shared_ptr<const ProjectiveInput> projective_input(std::shared_ptr<const MapInput> seen, const ReceiverPlane& r, const shadow::ProjectiveParams<Rational>& p);

// Per pixel, row 0 at the top: shadowed (-1: no surface, 0, 1) and, on the receiver's points, the
// exact visibility (-1 elsewhere). Over the receiver's points that face the light: missing, the
// shadowed ones not darkened (the depth tie lost); spurious, the lit ones darkened. off_receiver
// counts the darkened pixels that show another object (no stencil), doubled the darkenings of a
// pixel already dark; ties the fragments whose depth equalled the stored one.
struct ProjectivePixels {
  std::int64_t width = 0, height = 0;
  std::vector<int> shadowed, visible;
  std::int64_t missing = 0, spurious = 0, off_receiver = 0, doubled = 0, ties = 0, fragments = 0, occluders = 0;
  std::int64_t edge_ties = 0;  // the oracle's: pixels whose point lies on a shadow polygon's edge (GL's tie rule decided)
};
template <class Num> ProjectivePixels projective_pixels(const ProjectiveInput& in, const shadow::ProjectiveImage<Num>& img);
ProjectivePixels projected(const ProjectiveInput& in, Numeric n);
ProjectivePixels projective_oracle(const ProjectiveInput& in);
Json projective_json(const ProjectivePixels& p);
std::size_t projective_steps(const ProjectiveInput& in);
std::vector<BenchSet<ProjectiveInputRef>> projective_sets();

template <class Num> shadow::ProjectiveParams<Num> params_in(const shadow::ProjectiveParams<Rational>& p) {
  return {p.lequal, num::from_rational<Num>(p.factor), num::from_rational<Num>(p.units), p.stencil};
}

// The verdicts per pixel (top down) from a shadowed mask (rows bottom up, 0/1 per pixel).
ProjectivePixels projective_verdicts(const ProjectiveInput& in, const std::vector<char>& shadowed_bottom_up);
template <class Num> ProjectivePixels projective_pixels(const ProjectiveInput& in, const shadow::ProjectiveImage<Num>& img) {
  ProjectivePixels o = projective_verdicts(in, img.shadowed);
  o.off_receiver = img.off_receiver, o.doubled = img.doubled, o.ties = img.ties, o.fragments = img.fragments, o.occluders = img.occluders;
  return o;
}

}  // namespace sw::shadowspec
