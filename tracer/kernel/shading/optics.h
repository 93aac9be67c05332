// Reflection, refraction (Snell's law) and Fresnel reflectance for unit vectors.
#pragma once
#include "kernel/base/detmath.h"
#include "kernel/base/vec3.h"
#include "kernel/material/material.h"

namespace tracer {

// Mirror direction of d about the unit normal n.
TRACER_HD Vec3 reflect(Vec3 d, Vec3 n) { return d - n * (2.0f * dot(d, n)); }

// Snell's law's cos_t^2 = 1 - eta^2 (1 - cos_i^2) for relative index eta = n_incident /
// n_transmitted, negative on total internal reflection. Evaluated in double as
// (1 - eta^2) + eta^2 cos_i^2, whose first two products are exact: cos_t^2 comes out
// correctly rounded near the critical angle too, and eta = 1 gives cos_t = cos_i exactly.
// In float, 1 - cos_i^2 rounds to 1 below cos_i = 2^-12, which made cos_t 0 and IOR-1
// glass reflect totally at its silhouette.
TRACER_HD double transmitted_cos2(float cos_i, float eta) {
  const double eta2 = static_cast<double>(eta) * eta;
  return (1.0 - eta2) + eta2 * (static_cast<double>(cos_i) * cos_i);
}

// Refraction of unit d through a surface with unit normal n facing against d, relative
// index eta = n_incident / n_transmitted. Returns false on total internal reflection.
TRACER_HD bool refract(Vec3 d, Vec3 n, float eta, Vec3& out, float& cos_t) {
  const float cos_i = -dot(d, n);
  const double cos2_t = transmitted_cos2(cos_i, eta);
  if (cos2_t < 0.0) return false;
  cos_t = det_sqrt(static_cast<float>(cos2_t));
  out = d * eta + n * (eta * cos_i - cos_t);
  return true;
}

// Schlick's weight (1 - cos)^5, cos clamped to [0, 1].
TRACER_HD float schlick_weight(float cos_i) {
  const float m = clamp_of(1.0f - cos_i, 0.0f, 1.0f);
  const float m2 = m * m;
  return m2 * m2 * m;
}

// Schlick's approximation (Schlick 1994): R0 + (1 - R0)(1 - cos)^5 with
// R0 = ((n1 - n2)/(n1 + n2))^2; cos is the angle on the optically thinner side.
TRACER_HD float fresnel_schlick(float cos_thin_side, float n1, float n2) {
  const float r = (n1 - n2) / (n1 + n2);
  const float r0 = r * r;
  return r0 + (1.0f - r0) * schlick_weight(cos_thin_side);
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

// The same at a surface seen at cos_i from the side of index n_in: the transmitted cosine
// from Snell's law (computed as refract does), 1 on total internal reflection.
TRACER_HD float dielectric_reflectance_at(FresnelKind model, float cos_i, float n_in, float n_out) {
  const double cos2_t = transmitted_cos2(cos_i, n_in / n_out);
  if (cos2_t < 0.0) return 1.0f;
  return dielectric_reflectance(model, cos_i, det_sqrt(static_cast<float>(cos2_t)), n_in, n_out);
}

// Schlick's approximation with a reflectance at normal incidence per channel (a conductor's
// or glTF's F0): F0 + (1 - F0)(1 - cos)^5.
TRACER_HD Vec3 fresnel_schlick_f0(Vec3 f0, float cos_i) {
  return f0 + (Vec3{1.0f, 1.0f, 1.0f} - f0) * schlick_weight(cos_i);
}

// Exact Fresnel reflectance of unpolarised light on a conductor of complex index eta + i k
// (relative to the outside), one channel, in the real form of the s and p reflectances
// (Born and Wolf; as pbrt-v3's FrConductor): with a^2 + b^2 = sqrt((eta^2 - k^2 - sin^2)^2
// + 4 eta^2 k^2) and a = sqrt((a^2 + b^2 + eta^2 - k^2 - sin^2) / 2),
//   Rs = (a^2 + b^2 - 2 a cos + cos^2) / (a^2 + b^2 + 2 a cos + cos^2),
//   Rp = Rs (cos^2 (a^2 + b^2) - 2 a cos sin^2 + sin^4) / (cos^2 (a^2 + b^2) + 2 a cos sin^2 + sin^4).
TRACER_HD float fresnel_conductor(float cos_i, float eta, float k) {
  const float c = clamp_of(cos_i, 0.0f, 1.0f);
  const float cos2 = c * c, sin2 = (1.0f - c) * (1.0f + c);
  const float t0 = eta * eta - k * k - sin2;
  const float a2b2 = det_sqrt(t0 * t0 + 4.0f * (eta * eta) * (k * k));
  const float a = det_sqrt(max_of(0.0f, 0.5f * (a2b2 + t0)));
  const float t1 = a2b2 + cos2, t2 = 2.0f * a * c;
  // t1 + t2 is 0 only at grazing incidence on eta 1, k 0, which is no interface: no reflection.
  const float rs = t1 + t2 > 0.0f ? (t1 - t2) / (t1 + t2) : 0.0f;
  const float t3 = cos2 * a2b2 + sin2 * sin2, t4 = t2 * sin2;
  const float rp = rs * (t3 - t4) / (t3 + t4);
  return clamp_of(0.5f * (rs + rp), 0.0f, 1.0f);  // near eta 1, k 0 it rounds a few ulps below 0
}

TRACER_HD Vec3 fresnel_conductor(float cos_i, Vec3 eta, Vec3 k) {
  return {fresnel_conductor(cos_i, eta.x, k.x), fresnel_conductor(cos_i, eta.y, k.y),
          fresnel_conductor(cos_i, eta.z, k.z)};
}

}  // namespace tracer
