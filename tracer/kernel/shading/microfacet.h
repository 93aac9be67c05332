// The GGX (Trowbridge-Reitz) microfacet distribution with Smith shadowing, isotropic, in
// the local frame of the shading normal (+z). alpha = roughness^2 (glTF's and Disney's
// convention, docs/materials.md). Every quantity is written with the direction's components
// (x^2 + y^2 for sin^2, z for cos), so nothing cancels at small alpha or grazing angles.
//   D(m)      = alpha^2 / (pi (x^2 + y^2 + alpha^2 z^2)^2)          (Walter et al. 2007, eq. 33)
//   Lambda(w) = (sqrt(1 + alpha^2 tan^2) - 1) / 2                    (Heitz 2014, eq. 72)
//   G1(w)     = 1 / (1 + Lambda(w)),  G2(wo, wi) = 1 / (1 + Lambda(wo) + Lambda(wi))
//             (height-correlated, Heitz 2014 eq. 99, used for transmission too as pbrt-v4 does)
//   D_wo(m)   = G1(wo) max(0, wo.m) D(m) / wo.z                      (visible normals, Heitz 2014 eq. 38)
// sample_visible_normal draws m with density D_wo(m) by Dupuy and Benyoub's spherical caps
// (HPG 2023). Roughness below kSmoothRoughness takes the perfect mirror / smooth glass path.
#pragma once
#include "kernel/base/detmath.h"
#include "kernel/base/vec3.h"

namespace tracer {

// Below this roughness (alpha 1e-4) a microfacet material is treated as perfectly smooth:
// D would exceed 3e7 and its sampled normals differ from n by less than float resolution.
constexpr float kSmoothRoughness = 0.01f;

TRACER_HD float ggx_alpha(float roughness) { return roughness * roughness; }

TRACER_HD bool is_smooth(float roughness) { return roughness < kSmoothRoughness; }

TRACER_HD float sin2_of(Vec3 w) { return w.x * w.x + w.y * w.y; }

// D(m) for a unit m in the local frame; 0 below the surface.
TRACER_HD float ggx_d(Vec3 m, float alpha) {
  if (!(m.z > 0.0f)) return 0.0f;
  const float a2 = alpha * alpha;
  const float s = sin2_of(m) + a2 * (m.z * m.z);
  return a2 / (kPi * (s * s));
}

// Lambda(w) as alpha^2 sin^2 / (2 |z| (sqrt(z^2 + alpha^2 sin^2) + |z|)), which equals
// (sqrt(1 + alpha^2 tan^2) - 1) / 2 without its cancellation; infinite at z = 0.
TRACER_HD float ggx_lambda(Vec3 w, float alpha) {
  const float z = abs_of(w.z);
  const float t = (alpha * alpha) * sin2_of(w);
  if (t == 0.0f) return 0.0f;
  if (z == 0.0f) return kInfinity;
  return t / (2.0f * z * (det_sqrt(z * z + t) + z));
}

TRACER_HD float ggx_g1(Vec3 w, float alpha) { return 1.0f / (1.0f + ggx_lambda(w, alpha)); }

TRACER_HD float ggx_g2(Vec3 wo, Vec3 wi, float alpha) {
  return 1.0f / (1.0f + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha));
}

// D_wo(m): the density of the normals visible from wo (wo.z > 0) per solid angle of m.
TRACER_HD float ggx_visible_normal_pdf(Vec3 wo, Vec3 m, float alpha) {
  const float cos_om = dot(wo, m);
  if (!(cos_om > 0.0f) || !(wo.z > 0.0f)) return 0.0f;
  return ggx_g1(wo, alpha) * cos_om * ggx_d(m, alpha) / wo.z;
}

// A normal m with density D_wo(m), for wo.z > 0 (Dupuy and Benyoub 2023): in the
// configuration stretched to alpha 1, the visible normals are the points of the unit sphere's
// spherical cap below wo_std, offset by wo_std; unstretching gives m.
TRACER_HD Vec3 sample_visible_normal(Vec3 wo, float alpha, float u1, float u2) {
  const Vec3 wo_std = normalize(Vec3{wo.x * alpha, wo.y * alpha, wo.z});
  float sin_phi, cos_phi;
  det_sincos(2.0f * kPi * u1, sin_phi, cos_phi);
  const float z = (1.0f - u2) * (1.0f + wo_std.z) - wo_std.z;
  const float sin_theta = det_sqrt(max_of(0.0f, (1.0f - z) * (1.0f + z)));
  const Vec3 h = Vec3{sin_theta * cos_phi, sin_theta * sin_phi, z} + wo_std;
  return normalize(Vec3{h.x * alpha, h.y * alpha, h.z});
}

}  // namespace tracer
