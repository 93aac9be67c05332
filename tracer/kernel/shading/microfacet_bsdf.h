// The microfacet materials' BSDFs (docs/materials.md) on the GGX distribution of
// microfacet.h, in the local frame of the shading normal turned to wo's side (+z, wo.z > 0).
// Values are f(wo, wi) |wi.z| with their densities, as bsdf.h's.
//   conductor:        f = F(wo.h) D(h) G2 / (4 wo.z wi.z), h = normalize(wo + wi); F is Schlick's
//                     with albedo as F0, or the exact conductor Fresnel of eta + i k.
//   rough_dielectric: that reflection with the dielectric's F (Schlick or exact, on the
//                     microfacet), and transmission (Walter et al. 2007, eq. 21)
//                     f = tint (1 - F) D G2 |wi.h| |wo.h| / (wo.z |wi.z| (wi.h + wo.h / eta)^2)
//                     through the generalised half vector h = normalize(wo + eta wi),
//                     eta = n(wi's side) / n(wo's side). No 1/eta^2 radiance scaling, as the
//                     smooth dielectric, so f(wo, wi) n(wo)^2 = f(wi, wo) n(wi)^2.
//   metal_rough:      glTF 2.0's BRDF (specification, appendix B): mix(dielectric, metal,
//                     metallic), metal = spec Schlick(base colour), dielectric =
//                     fresnel_mix(F0 from ior, (1 - transmission) base / pi, spec), where the
//                     transmission (KHR_materials_transmission, thin-walled: no volume) is spec
//                     tinted by base, mirrored through the surface; Fresnel at wo.h.
// Sampling: a visible normal, reflected (conductor); reflected with probability F, else
// refracted (rough_dielectric), each weighing G2 / G1(wo); metal_rough picks its specular,
// diffuse or transmission lobe (metal_rough_lobes) and weighs f / the mixture's density.
#pragma once
#include "kernel/shading/bsdf_sample.h"
#include "kernel/shading/material.h"
#include "kernel/shading/microfacet.h"
#include "kernel/shading/optics.h"
#include "kernel/shading/sampling.h"

namespace tracer {

TRACER_HD Vec3 conductor_fresnel(const Material& m, float cos_oh) {
  return m.fresnel == FresnelKind::Exact ? fresnel_conductor(cos_oh, m.eta, m.k) : fresnel_schlick_f0(m.albedo, cos_oh);
}

// The specular reflection lobe without its Fresnel factor: f cos = D G2 / (4 wo.z) and the
// density D_wo(h) / (4 wo.h) of reflecting a visible normal (the Jacobian of h -> wi).
struct SpecularLobe {
  float f_cos, pdf, cos_oh;
};

TRACER_HD SpecularLobe specular_reflection(Vec3 wo, Vec3 wi, float alpha) {
  SpecularLobe r = {0.0f, 0.0f, 0.0f};
  const Vec3 sum = wo + wi;
  const float len = length(sum);
  if (!(wi.z > 0.0f) || !(len > 0.0f)) return r;
  const Vec3 h = sum / len;
  r.cos_oh = dot(wo, h);
  if (!(r.cos_oh > 0.0f)) return r;
  r.f_cos = ggx_d(h, alpha) * ggx_g2(wo, wi, alpha) / (4.0f * wo.z);
  r.pdf = ggx_visible_normal_pdf(wo, h, alpha) / (4.0f * r.cos_oh);
  return r;
}

// The transmission lobe without its (1 - F) factor, for wi.z < 0 and eta = n(wi) / n(wo):
// f cos = D G2 |wi.h| wo.h / (wo.z (wi.h + wo.h / eta)^2) and the density D_wo(h) |wi.h| /
// (wi.h + wo.h / eta)^2 (Walter et al. 2007, eq. 17). Microfacets facing away from wo or
// toward wi give 0.
TRACER_HD SpecularLobe specular_transmission(Vec3 wo, Vec3 wi, float eta, float alpha) {
  SpecularLobe r = {0.0f, 0.0f, 0.0f};
  Vec3 h = wo + wi * eta;
  const float len = length(h);
  if (!(wi.z < 0.0f) || !(len > 0.0f)) return r;
  h = h.z < 0.0f ? -h / len : h / len;
  const float cos_oh = dot(wo, h), cos_ih = dot(wi, h);
  const float denom = cos_ih + cos_oh / eta;
  if (!(cos_oh > 0.0f) || !(cos_ih < 0.0f) || denom == 0.0f) return r;
  const float jacobian = -cos_ih / (denom * denom);
  r.cos_oh = cos_oh;
  r.f_cos = ggx_d(h, alpha) * ggx_g2(wo, wi, alpha) * cos_oh * jacobian / wo.z;
  r.pdf = ggx_visible_normal_pdf(wo, h, alpha) * jacobian;
  return r;
}

// A visible normal's mirror direction: wi = 2 (wo.h) h - wo.
TRACER_HD Vec3 reflect_about(Vec3 wo, Vec3 h) { return h * (2.0f * dot(wo, h)) - wo; }

TRACER_HD BsdfValue eval_conductor(const Material& m, Vec3 wo, Vec3 wi) {
  const SpecularLobe r = specular_reflection(wo, wi, ggx_alpha(m.roughness));
  return {conductor_fresnel(m, r.cos_oh) * r.f_cos, r.pdf};
}

TRACER_HD bool sample_conductor(const Material& m, Vec3 wo, float u1, float u2, BsdfSample& s) {
  const float alpha = ggx_alpha(m.roughness);
  const Vec3 h = sample_visible_normal(wo, alpha, u1, u2);
  s.wi = reflect_about(wo, h);
  if (!(s.wi.z > 0.0f)) return false;
  s.weight = conductor_fresnel(m, dot(wo, h)) * (ggx_g2(wo, s.wi, alpha) / ggx_g1(wo, alpha));
  s.pdf = ggx_visible_normal_pdf(wo, h, alpha) / (4.0f * dot(wo, h));
  return s.pdf > 0.0f;
}

// Indices of refraction on wo's and on the other side; `front`: wo is outside.
TRACER_HD void dielectric_sides(const Material& m, bool front, float& n_wo, float& n_other) {
  n_wo = front ? 1.0f : m.ior;
  n_other = front ? m.ior : 1.0f;
}

TRACER_HD BsdfValue eval_rough_dielectric(const Material& m, Vec3 wo, Vec3 wi, bool front) {
  float n_wo, n_other;
  dielectric_sides(m, front, n_wo, n_other);
  const float alpha = ggx_alpha(m.roughness);
  const BsdfValue none = {{0.0f, 0.0f, 0.0f}, 0.0f};  // also keeps exact Fresnel off cos 0 at ior 1 (0 / 0)
  if (wi.z > 0.0f) {
    const SpecularLobe r = specular_reflection(wo, wi, alpha);
    if (!(r.cos_oh > 0.0f)) return none;
    const float f = dielectric_reflectance_at(m.fresnel, r.cos_oh, n_wo, n_other);
    return {Vec3{1.0f, 1.0f, 1.0f} * (f * r.f_cos), f * r.pdf};
  }
  const SpecularLobe t = specular_transmission(wo, wi, n_other / n_wo, alpha);
  if (n_wo == n_other || !(t.cos_oh > 0.0f)) return none;  // index-matched: a delta (sample_rough_dielectric)
  const float f = 1.0f - dielectric_reflectance_at(m.fresnel, t.cos_oh, n_wo, n_other);
  return {m.tint * (f * t.f_cos), f * t.pdf};
}

TRACER_HD bool sample_rough_dielectric(const Material& m, Vec3 wo, bool front, float u_choice, float u1, float u2,
                                       BsdfSample& s) {
  float n_wo, n_other;
  dielectric_sides(m, front, n_wo, n_other);
  const float alpha = ggx_alpha(m.roughness);
  const Vec3 h = sample_visible_normal(wo, alpha, u1, u2);
  const float cos_oh = dot(wo, h);
  const float f = dielectric_reflectance_at(m.fresnel, cos_oh, n_wo, n_other);
  const float visible = ggx_visible_normal_pdf(wo, h, alpha);
  float cos_t;
  if (u_choice < f) {
    s.wi = reflect_about(wo, h);
    if (!(s.wi.z > 0.0f)) return false;
    s.weight = Vec3{1.0f, 1.0f, 1.0f} * (ggx_g2(wo, s.wi, alpha) / ggx_g1(wo, alpha));
    s.pdf = f * visible / (4.0f * cos_oh);
  } else if (n_wo == n_other) {
    // Index-matched glass: every microfacet passes wo straight on and Walter's half vector
    // is undefined; a delta transmission, as the smooth dielectric's.
    s = {-wo, m.tint, 0.0f, true};
    return true;
  } else {
    if (!refract(-wo, h, n_wo / n_other, s.wi, cos_t) || !(s.wi.z < 0.0f)) return false;
    const float denom = dot(s.wi, h) + cos_oh * n_wo / n_other;
    s.weight = m.tint * (ggx_g2(wo, s.wi, alpha) / ggx_g1(wo, alpha));
    s.pdf = (1.0f - f) * visible * -dot(s.wi, h) / (denom * denom);
  }
  return s.pdf > 0.0f && s.pdf < kInfinity;
}

// metal_rough's lobe probabilities seen from wo: specular metallic + (1 - metallic) F(wo.z),
// the rest split into diffuse and thin-walled transmission by `transmission`. F is Schlick's
// from air into ior, whose R0 is glTF's dielectric F0 ((ior - 1) / (ior + 1))^2.
struct MetalRoughLobes {
  float specular, diffuse, transmission;
};

TRACER_HD MetalRoughLobes metal_rough_lobes(const Material& m, float cos_o) {
  const float specular = m.metallic + (1.0f - m.metallic) * fresnel_schlick(cos_o, 1.0f, m.ior);
  const float rest = 1.0f - specular;
  return {specular, rest * (1.0f - m.transmission), rest * m.transmission};
}

// metal_rough's roughness is never treated as smooth: it has a diffuse lobe beside the specular.
TRACER_HD float metal_rough_alpha(const Material& m) { return ggx_alpha(max_of(m.roughness, kSmoothRoughness)); }

TRACER_HD BsdfValue eval_metal_rough(const Material& m, Vec3 wo, Vec3 wi) {
  const bool transmitted = wi.z < 0.0f;
  const Vec3 wr = {wi.x, wi.y, abs_of(wi.z)};  // the thin-walled transmission mirrors the reflection
  const SpecularLobe r = specular_reflection(wo, wr, metal_rough_alpha(m));
  const MetalRoughLobes p = metal_rough_lobes(m, wo.z);
  const float fd = fresnel_schlick(r.cos_oh, 1.0f, m.ior);
  if (transmitted)
    return {m.albedo * ((1.0f - m.metallic) * (1.0f - fd) * m.transmission * r.f_cos), p.transmission * r.pdf};
  if (!(wi.z > 0.0f)) return {{0.0f, 0.0f, 0.0f}, 0.0f};
  const Vec3 metal = fresnel_schlick_f0(m.albedo, r.cos_oh) * r.f_cos;
  const Vec3 dielectric =
      m.albedo * ((1.0f - fd) * (1.0f - m.transmission) * wi.z / kPi) + Vec3{1.0f, 1.0f, 1.0f} * (fd * r.f_cos);
  return {dielectric * (1.0f - m.metallic) + metal * m.metallic, p.specular * r.pdf + p.diffuse * wi.z / kPi};
}

TRACER_HD bool sample_metal_rough(const Material& m, Vec3 wo, float u_choice, float u1, float u2, BsdfSample& s) {
  const MetalRoughLobes p = metal_rough_lobes(m, wo.z);
  if (u_choice < p.specular || u_choice >= 1.0f - p.transmission) {
    s.wi = reflect_about(wo, sample_visible_normal(wo, metal_rough_alpha(m), u1, u2));
    if (!(s.wi.z > 0.0f)) return false;
    if (!(u_choice < p.specular)) s.wi.z = -s.wi.z;
  } else {
    s.wi = sample_cosine_hemisphere(u1, u2);
  }
  const BsdfValue v = eval_metal_rough(m, wo, s.wi);
  s.pdf = v.pdf;
  if (!(s.pdf > 0.0f)) return false;
  s.weight = v.f_cos / s.pdf;
  return true;
}

}  // namespace tracer
