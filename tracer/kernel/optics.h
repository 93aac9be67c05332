// Reflection, refraction (Snell's law) and Fresnel reflectance for unit vectors.
#pragma once
#include "detmath.h"
#include "material.h"
#include "vec3.h"

namespace tracer {

// Mirror direction of d about the unit normal n.
TRACER_HD Vec3 reflect(Vec3 d, Vec3 n) { return d - n * (2.0f * dot(d, n)); }

// Refraction of unit d through a surface with unit normal n facing against d, relative
// index eta = n_incident / n_transmitted. Returns false on total internal reflection,
// i.e. when eta^2 (1 - cos_i^2) > 1 (sin of the transmitted angle above 1).
TRACER_HD bool refract(Vec3 d, Vec3 n, float eta, Vec3& out, float& cos_t) {
  const float cos_i = -dot(d, n);
  const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
  if (sin2_t > 1.0f) return false;
  cos_t = det_sqrt(1.0f - sin2_t);
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
