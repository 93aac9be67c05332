// What every material kind answers, and the answer where a kind says nothing. Each kind is a
// struct in its own header (material_kinds.h lists them) deriving from MaterialKindBase and
// defining, as static member functions usable from CUDA:
//   eval(m, wo, wi, n, front)   f(wo, wi) |cos(n, wi)| and the density sample() picks wi with;
//                               0 for the specular (delta) choices
//   sample(m, wo, n, front, u_choice, u1, u2, s)   a direction and its weight (false: absorbed)
//   whitted(m, cos_o)           its terms in Whitted's model (WhittedResponse)
// and, where the default below is not its answer, hiding it:
//   is_specular(m)              its only choices are deltas: sample() reads no direction pair
//   uses_choice(m)              sample() reads u_choice (a lobe, or Fresnel's reflect/refract)
//   albedo(m)                   the albedo view's colour
//   apply_factor_map(m, f)      a factor texture's value f applied to its parameters
//   is_perfect_mirror(m)        a specular reflection alone, whose light images can be sampled
//   mirror_reflectance(m, cos)  what such a mirror reflects of light arriving at cos
// wo points from the surface toward the previous vertex, n is the unit shading normal flipped to
// wo's side, `front` says wo is on the side the geometric normal points to; all in world space.
#pragma once
#include "kernel/material/material.h"
#include "kernel/shading/bsdf_sample.h"
#include "kernel/shading/sampling.h"

namespace tracer {

// The classic model's coefficients for one material (kernel/integrator/whitted.h).
struct WhittedResponse {
  Vec3 ka, kd, ks;  // ambient, diffuse, specular reflectance
  float shininess;
  Vec3 kr;  // mirror reflection weight
  Vec3 kt;  // transmission weight, split by Fresnel into reflection and refraction
  float ior;
  FresnelKind fresnel;
  Vec3 emission;
  bool two_sided;
  bool brdf;  // point lights reflect by the material's BSDF f cos (the microfacet kinds), not kd and ks
};

struct MaterialKindBase {
  // The response of a material that neither reflects nor transmits: its emission only.
  TRACER_HD static WhittedResponse whitted_emission_only(const Material& m) {
    const Vec3 zero = {0.0f, 0.0f, 0.0f};
    return {zero, zero, zero, 1.0f, zero, zero, 1.0f, m.fresnel, m.radiance, m.two_sided != 0, false};
  }
  TRACER_HD static bool is_specular(const Material&) { return false; }
  TRACER_HD static bool uses_choice(const Material&) { return false; }
  TRACER_HD static Vec3 albedo(const Material& m) { return m.albedo; }
  TRACER_HD static void apply_factor_map(Material& m, Vec3 f) { m.specular = m.specular * f; }
  TRACER_HD static bool is_perfect_mirror(const Material&) { return false; }
  TRACER_HD static Vec3 mirror_reflectance(const Material&, float) { return {0.0f, 0.0f, 0.0f}; }
};

}  // namespace tracer
