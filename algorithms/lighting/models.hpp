// Every reflection model, and the dispatchers shade calls (declared in brdf.hpp): diffuse_term and
// specular_term run one model's term on a frame inside the model's own nested listing (toon: the
// toon listing, with the diffuse model nested in it), and give 0 below the horizon without a step.
// evaluate() is the whole model from raw vectors: the frame's steps, then the term, on the model's
// own listing (the runtime's entries). Semantics: docs/lighting/semantics.md.
#pragma once
#include <string_view>
#include "lighting/cook_torrance.hpp"
#include "lighting/gaussian.hpp"
#include "lighting/phong.hpp"
#include "lighting/toon.hpp"
#include "lighting/ward.hpp"

namespace sw::lighting {

template <NumberType Num, StepProbe Probe>
Num diffuse_term(DiffuseModel m, const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  if (!(f.lit && f.seen)) return Num(0);
  if (!p.toon) return diffuse_nested(m, f, p, probe);
  const auto call = nested<Toon>(probe);
  return toon_term(m, f, p, probe);
}

// The specular model's term on a lit and seen frame, on the model's listing (not entered).
template <NumberType Num, StepProbe Probe>
Num specular_plain(SpecularModel m, const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  switch (m) {
    case SpecularModel::none: return Num(0);
    case SpecularModel::phong: return phong_term(f, p, probe);
    case SpecularModel::blinn_phong: return blinn_phong_term(f, p, probe);
    case SpecularModel::gaussian: return gaussian_term(f, p, probe);
    case SpecularModel::beckmann: return beckmann_term(f, p, probe);
    case SpecularModel::cook_torrance: return cook_torrance_term(f, p, probe);
    case SpecularModel::ward: return ward_term(f, p, probe);
  }
  return Num(0);
}

template <NumberType Num, StepProbe Probe>
Num specular_term(SpecularModel m, const Frame<Num>& f, const ModelParams<Num>& p, Probe& probe) {
  if (!(f.lit && f.seen) || m == SpecularModel::none) return Num(0);
  auto run = [&]<class Algo>(std::type_identity<Algo>) -> Num {
    const auto call = nested<Algo>(probe);
    return specular_plain(m, f, p, probe);
  };
  switch (m) {
    case SpecularModel::phong: return run(std::type_identity<Phong>{});
    case SpecularModel::blinn_phong: return run(std::type_identity<BlinnPhong>{});
    case SpecularModel::gaussian: return run(std::type_identity<Gaussian>{});
    case SpecularModel::beckmann: return run(std::type_identity<Beckmann>{});
    case SpecularModel::cook_torrance: return run(std::type_identity<CookTorrance>{});
    case SpecularModel::ward: return run(std::type_identity<Ward>{});
    case SpecularModel::none: break;
  }
  return Num(0);
}

inline std::string_view model_name(DiffuseModel m) {
  switch (m) {
    case DiffuseModel::lambert: return Lambert::id;
    case DiffuseModel::minnaert: return Minnaert::id;
    case DiffuseModel::oren_nayar: return OrenNayar::id;
  }
  return "?";
}
inline std::string_view model_name(SpecularModel m) {
  switch (m) {
    case SpecularModel::none: return "none";
    case SpecularModel::phong: return Phong::id;
    case SpecularModel::blinn_phong: return BlinnPhong::id;
    case SpecularModel::gaussian: return Gaussian::id;
    case SpecularModel::beckmann: return Beckmann::id;
    case SpecularModel::cook_torrance: return CookTorrance::id;
    case SpecularModel::ward: return Ward::id;
  }
  return "?";
}

// The whole model on raw N, L, E (non-zero) with its steps on listing L: the frame, then the term
// (the diffuse model inside toon runs nested). `given`: the decisions made on the exact input;
// frame_out, if set, receives the frame.
template <class L, NumberType Num, StepProbe Probe>
Num evaluate(const ModelChoice& c, const Vec3<Num>& N, const Vec3<Num>& Lv, const Vec3<Num>& E, const ModelParams<Num>& p,
             Probe& probe, const std::optional<FrameSigns>& given = std::nullopt, Frame<Num>* frame_out = nullptr) {
  const Frame<Num> f = shading_frame<L>(N, Lv, E, probe, given);
  if (frame_out) *frame_out = f;
  return frame_term<L>(f, probe, [&]() -> Num {
    if (c.specular) return specular_plain(c.spec, f, p, probe);
    if (p.toon) return toon_term(c.diffuse, f, p, probe);
    switch (c.diffuse) {
      case DiffuseModel::minnaert: return minnaert_term(f, p, probe);
      case DiffuseModel::oren_nayar: return oren_nayar_term(f, p, probe);
      case DiffuseModel::lambert: break;
    }
    return lambert_term(f, p, probe);
  });
}

}  // namespace sw::lighting
