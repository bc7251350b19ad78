// ray-plane and ray-box in the catalog (ray_spec.hpp).
#include "rays/ray_spec.hpp"
#include "rays/ray_box.hpp"
#include "rays/ray_plane.hpp"

namespace sw::rays {
namespace {

struct BoxSpec : RaySpec<ray::RayBox, Prim::box> {
  static inline const std::string example = R"({"ray":{"o":[0,1,0.5],"d":[1,-0.0,0]},"box":{"min":[1,0,0],"max":[2,1,1]}})";
  template <class Num, class Probe> [[gnu::always_inline]] static RayOutput compute(const Prepared<Num>& p, Probe& probe) {
    const auto h = ray::RayBox{}(p.ray, p.v[0], p.v[1], probe);
    return make_output<Num>(h.hit, h.t, true, nullptr, &h.t_near, &h.t_far);
  }
};
struct PlaneSpec : RaySpec<ray::RayPlane, Prim::plane> {
  static inline const std::string example = R"({"ray":{"o":[0,0,1],"d":[1,0,-0.001]},"plane":{"p":[0,0,0],"n":[0,0,1]}})";
  template <class Num, class Probe> [[gnu::always_inline]] static RayOutput compute(const Prepared<Num>& p, Probe& probe) {
    const auto h = ray::RayPlane{}(p.ray, p.v[0], p.v[1], probe);
    return make_output<Num>(h.hit, h.t, true, nullptr, nullptr, nullptr);
  }
};

}  // namespace

SW_REGISTER(PlaneSpec);
SW_REGISTER(BoxSpec);

}  // namespace sw::rays
