#include "shadows/scene_shadows.hpp"
#include "tracer/plan.hpp"

namespace sw::shadowspec {

SceneShadows scene_shadows(const std::shared_ptr<const RasterScene>& s, ShadowMethod method, const MapOptions& o, Numeric n, bool all_effects,
                           std::int64_t receiver) {
  const tracer::Plan plan = all_effects ? tracer::all_effects_plan(*s->scene) : tracer::plan_scene(*s->scene);
  const pipespec::RasterTruth truth = pipespec::raster_truth(*s, 0);
  SceneShadows out{method, std::vector<std::uint32_t>(std::size_t(s->width * s->height), 0), {}};
  for (std::size_t i = 0; i < s->scene->lights.size(); ++i) {
    LightShadows l{i, plan.effects.shadows[i] != 0, {}, nullptr, {}, nullptr, {}, nullptr, {}};
    if (!l.pass) {
      const std::string name = "light " + std::to_string(i) + " ";
      for (const tracer::Decision& d : plan.decisions)
        if (d.effect == "shadows" && d.subject.rfind(name, 0) == 0) l.skipped = d.reason;
      out.lights.push_back(std::move(l));
      continue;
    }
    l.in = method == ShadowMethod::map ? map_input(s, i, o, truth, 0) : seen_input(s, i, truth, 0);
    std::vector<int> lit;
    if (method == ShadowMethod::map) {
      l.map = looked_up(*l.in, n);
      lit = l.map.lit;
    } else if (method == ShadowMethod::projective) {
      l.projective_in = projective_input(l.in, receiver_plane(*s, i, receiver), shadow::ProjectiveParams<Rational>{false, Rational(-1), Rational(-1), true});
      l.projective = projected(*l.projective_in, n);
      lit.assign(l.projective.shadowed.size(), -1);
      for (std::size_t k = 0; k < lit.size(); ++k)
        if (l.projective.shadowed[k] >= 0) lit[k] = 1 - l.projective.shadowed[k];
    } else {
      l.volume_in = volume_input(l.in, method == ShadowMethod::volume_zfail);
      l.volume = stenciled(*l.volume_in, n);
      lit = l.volume.lit;
    }
    for (std::size_t k = 0; k < lit.size(); ++k)
      if (lit[k] == 0) out.blocked[k] |= 1u << i;
    out.lights.push_back(std::move(l));
  }
  return out;
}

}  // namespace sw::shadowspec
