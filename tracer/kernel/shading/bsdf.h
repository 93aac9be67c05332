// Scattering for the path integrator, one switch per operation over the material kinds
// (docs/materials.md). wo points from the surface toward the previous vertex, n is the
// unit shading normal flipped to wo's side, wi the sampled or queried direction; all in
// world space. eval_bsdf returns f(wo, wi) |cos(n, wi)| and the solid-angle density with
// which sample_bsdf picks wi; both are 0 for specular (delta) choices.
//   lambert:    f = albedo / pi, cosine-weighted sampling.
//   metal:      roughness 0 is a mirror tinted by albedo. Otherwise a Phong lobe
//               cos^e(alpha) about the mirror direction, e = 2 / roughness^2 - 2, sampled
//               exactly, with f cos = albedo (e + 1) / (2 pi) cos^e(alpha): each sample
//               weighs albedo, and lobe directions below the surface are absorbed.
//   dielectric: reflection or refraction chosen by the Fresnel reflectance (Schlick or
//               exact), total internal reflection always reflects; refraction is tinted.
//   phong:      the normalised modified Phong BRDF (Lafortune and Willems 1994),
//               kd / pi + ks (e + 2) / (2 pi) cos^e(alpha), sampled by picking the diffuse
//               or the specular lobe in proportion to their luminance.
//   emissive:   Lambertian with its optional albedo (0 by default: black).
//   conductor, rough_dielectric, metal_rough: GGX microfacet BSDFs (microfacet_bsdf.h),
//               evaluated and sampled in the frame of n; below kSmoothRoughness the conductor
//               is a mirror tinted by its Fresnel reflectance and the rough dielectric is the
//               smooth one. Only these may return a wi below n (transmission) from eval_bsdf.
#pragma once
#include "kernel/shading/bsdf_sample.h"
#include "kernel/shading/material.h"
#include "kernel/shading/microfacet_bsdf.h"
#include "kernel/shading/optics.h"
#include "kernel/shading/sampling.h"

namespace tracer {

TRACER_HD float metal_exponent(float roughness) { return 2.0f / (roughness * roughness) - 2.0f; }

TRACER_HD bool is_microfacet(MaterialKind kind) {
  return kind == MaterialKind::Conductor || kind == MaterialKind::RoughDielectric || kind == MaterialKind::MetalRough;
}

TRACER_HD bool is_specular(const Material& m) {
  return m.kind == MaterialKind::Dielectric || (m.kind == MaterialKind::Metal && m.roughness == 0.0f) ||
         ((m.kind == MaterialKind::Conductor || m.kind == MaterialKind::RoughDielectric) && is_smooth(m.roughness));
}

// Whether sample_bsdf reads u_choice (a lobe, or Fresnel's reflect/refract); it reads (u1, u2)
// exactly when the material is not specular. The path tracer draws only the numbers read.
TRACER_HD bool bsdf_uses_choice(const Material& m) {
  return m.kind == MaterialKind::Dielectric || m.kind == MaterialKind::RoughDielectric ||
         m.kind == MaterialKind::MetalRough || m.kind == MaterialKind::Phong;
}

// A microfacet material's value in the frame of n (wo on n's side; `front`: wo is outside).
TRACER_HD BsdfValue eval_microfacet(const Material& m, Vec3 wo, Vec3 wi, Vec3 n, bool front) {
  const Frame f = frame_around(n);
  const Vec3 o = f.to_local(wo), i = f.to_local(wi);
  if (!(o.z > 0.0f) || is_specular(m)) return {{0.0f, 0.0f, 0.0f}, 0.0f};
  if (m.kind == MaterialKind::Conductor) return eval_conductor(m, o, i);
  if (m.kind == MaterialKind::RoughDielectric) return eval_rough_dielectric(m, o, i, front);
  return eval_metal_rough(m, o, i);
}

TRACER_HD bool sample_microfacet(const Material& m, Vec3 wo, Vec3 n, bool front, float u_choice, float u1, float u2,
                                 BsdfSample& s) {
  const Frame f = frame_around(n);
  const Vec3 o = f.to_local(wo);
  s.specular = false;
  if (!(o.z > 0.0f)) return false;
  bool ok = false;
  if (m.kind == MaterialKind::Conductor) ok = sample_conductor(m, o, u1, u2, s);
  if (m.kind == MaterialKind::RoughDielectric) ok = sample_rough_dielectric(m, o, front, u_choice, u1, u2, s);
  if (m.kind == MaterialKind::MetalRough) ok = sample_metal_rough(m, o, u_choice, u1, u2, s);
  s.wi = f.to_world(s.wi);
  return ok;
}

// Probability of sampling phong's diffuse lobe rather than its specular one.
TRACER_HD float phong_diffuse_probability(const Material& m) {
  const float d = luminance(m.albedo), s = luminance(m.specular);
  return d + s > 0.0f ? d / (d + s) : 1.0f;
}

TRACER_HD BsdfValue eval_bsdf(const Material& m, Vec3 wo, Vec3 wi, Vec3 n, bool front) {
  if (is_microfacet(m.kind)) return eval_microfacet(m, wo, wi, n, front);
  const float cos_i = dot(wi, n);
  BsdfValue v = {{0.0f, 0.0f, 0.0f}, 0.0f};
  if (!(cos_i > 0.0f)) return v;
  switch (m.kind) {
    case MaterialKind::Lambert:
    case MaterialKind::Emissive:
      v.f_cos = m.albedo * (cos_i / kPi);
      v.pdf = cos_i / kPi;
      return v;
    case MaterialKind::Metal:
      if (m.roughness == 0.0f) return v;
      v.pdf = phong_lobe_pdf(metal_exponent(m.roughness), dot(wi, reflect(-wo, n)));
      v.f_cos = m.albedo * v.pdf;
      return v;
    case MaterialKind::Phong: {
      const float cos_a = dot(wi, reflect(-wo, n));
      const float power = det_pow(max_of(cos_a, 0.0f), m.shininess);
      const float lobe = (m.shininess + 2.0f) / (2.0f * kPi) * power;
      v.f_cos = m.albedo * (cos_i / kPi) + m.specular * (lobe * cos_i);
      const float pd = phong_diffuse_probability(m);
      const float lobe_pdf = cos_a > 0.0f ? (m.shininess + 1.0f) / (2.0f * kPi) * power : 0.0f;  // phong_lobe_pdf
      v.pdf = pd * cos_i / kPi + (1.0f - pd) * lobe_pdf;
      return v;
    }
    default: break;  // the dielectric is specular; the microfacet kinds returned above
  }
  return v;
}

// `front`: wo is on the side the geometric normal points to (outside a dielectric).
// u_choice picks a lobe or Fresnel's reflect/refract; (u1, u2) the direction. False when
// the path is absorbed (a black material, a lobe direction below the surface).
TRACER_HD bool sample_bsdf(const Material& m, Vec3 wo, Vec3 n, bool front, float u_choice, float u1, float u2,
                           BsdfSample& s) {
  s.specular = false;
  switch (m.kind) {
    case MaterialKind::Lambert:
    case MaterialKind::Emissive: {
      if (!(max_component(m.albedo) > 0.0f)) return false;
      const Vec3 local = sample_cosine_hemisphere(u1, u2);
      s.wi = frame_around(n).to_world(local);
      s.pdf = local.z / kPi;
      s.weight = m.albedo;
      return local.z > 0.0f;
    }
    case MaterialKind::Metal: {
      const Vec3 mirror = reflect(-wo, n);
      if (m.roughness == 0.0f) {
        s = {mirror, m.albedo, 0.0f, true};
        return true;
      }
      const float e = metal_exponent(m.roughness);
      const Vec3 local = sample_phong_lobe(e, u1, u2);
      s.wi = frame_around(mirror).to_world(local);
      s.pdf = phong_lobe_pdf(e, local.z);
      s.weight = m.albedo;
      return dot(s.wi, n) > 0.0f && s.pdf > 0.0f;
    }
    case MaterialKind::Conductor:
      if (!is_smooth(m.roughness)) return sample_microfacet(m, wo, n, front, u_choice, u1, u2, s);
      s = {reflect(-wo, n), conductor_fresnel(m, dot(wo, n)), 0.0f, true};
      return true;
    case MaterialKind::MetalRough: return sample_microfacet(m, wo, n, front, u_choice, u1, u2, s);
    case MaterialKind::RoughDielectric:
      if (!is_smooth(m.roughness)) return sample_microfacet(m, wo, n, front, u_choice, u1, u2, s);
      [[fallthrough]];  // the smooth dielectric
    case MaterialKind::Dielectric: {
      const float n_in = front ? 1.0f : m.ior, n_out = front ? m.ior : 1.0f;
      const Vec3 d = -wo;
      Vec3 refracted;
      float cos_t;
      const Vec3 one = {1.0f, 1.0f, 1.0f};
      if (refract(d, n, n_in / n_out, refracted, cos_t) &&
          !(u_choice < dielectric_reflectance(m.fresnel, dot(wo, n), cos_t, n_in, n_out))) {
        s = {refracted, m.tint, 0.0f, true};
      } else {
        s = {reflect(d, n), one, 0.0f, true};  // Fresnel reflection or total internal reflection
      }
      return true;
    }
    case MaterialKind::Phong: {
      const float pd = phong_diffuse_probability(m);
      if (!(max_component(m.albedo) > 0.0f || max_component(m.specular) > 0.0f)) return false;
      const Vec3 local = u_choice < pd ? sample_cosine_hemisphere(u1, u2) : sample_phong_lobe(m.shininess, u1, u2);
      s.wi = frame_around(u_choice < pd ? n : reflect(-wo, n)).to_world(local);
      const BsdfValue v = eval_bsdf(m, wo, s.wi, n, front);
      s.pdf = v.pdf;
      if (!(s.pdf > 0.0f)) return false;
      s.weight = v.f_cos / s.pdf;
      return true;
    }
  }
  return false;
}

}  // namespace tracer
