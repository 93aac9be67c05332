// Reflection, refraction (Snell's law) and Fresnel reflectance for unit vectors.
#pragma once
#include "kernel/base/detmath.h"
#include "kernel/base/vec3.h"
#include "kernel/shading/material.h"

namespace tracer {

// Mirror direction of d about the unit normal n.
TRACER_HD Vec3 reflect(Vec3 d, Vec3 n) { return d - n * (2.0f * dot(d, n)); }

// Refraction of unit d through a surface with unit normal n facing against d, relative
// index eta = n_incident / n_transmitted. Returns false on total internal reflection,
// i.e. when cos_t^2 = 1 - eta^2 (1 - cos_i^2) < 0. Evaluated in double as
// (1 - eta^2) + eta^2 cos_i^2, whose first two products are exact: cos_t^2 comes out
// correctly rounded near the critical angle too, and eta = 1 gives cos_t = cos_i exactly.
// In float, 1 - cos_i^2 rounds to 1 below cos_i = 2^-12, which made cos_t 0 and IOR-1
// glass reflect totally at its silhouette.
TRACER_HD bool refract(Vec3 d, Vec3 n, float eta, Vec3& out, float& cos_t) {
  const float cos_i = -dot(d, n);
  const double eta2 = static_cast<double>(eta) * eta;
  const double cos2_t = (1.0 - eta2) + eta2 * (static_cast<double>(cos_i) * cos_i);
  if (cos2_t < 0.0) return false;
  cos_t = det_sqrt(static_cast<float>(cos2_t));
  out = d * eta + n * (eta * cos_i - cos_t);
  return true;
}

// Schlick's approximation (Schlick 1994): R0 + (1 - R0)(1 - cos)^5 with
// R0 = ((n1 - n2)/(n1 + n2))^2; cos is the angle on the optically thinner side.
TRACER_HD float fresnel_schlick(float cos_thin_side, float n1, float n2) {
  const float r = (n1 - n2) / (n1 + n2);
  const float r0 = r * r;
  const float m = clamp_of(1.0f - cos_thin_side, 0.0f, 1.0f);
  const float m2 = m * m;
  return r0 + (1.0f - r0) * (m2 * m2 * m);
}

// Exact Fresnel reflectance of unpolarised light for a dielectric interface (the mean of
// the s and p reflectances), given both cosines; 1 on total internal reflection.
TRACER_HD float fresnel_exact(float cos_i, float cos_t, float n1, float n2) {
  const float rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
  const float rp = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
  return 0.5f * (rs * rs + rp * rp);
}

// Reflectance of a dielectric interface by the material's Fresnel model; Schlick takes
// the cosine on the optically thinner side.
TRACER_HD float dielectric_reflectance(FresnelKind model, float cos_i, float cos_t, float n_in, float n_out) {
  return model == FresnelKind::Exact ? fresnel_exact(cos_i, cos_t, n_in, n_out)
                                     : fresnel_schlick(n_in <= n_out ? cos_i : cos_t, n_in, n_out);
}

}  // namespace tracer
