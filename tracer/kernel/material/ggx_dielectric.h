// rough_dielectric (MaterialKind::GgxDielectric): GGX microfacet glass. Reflection as the
// conductor's with the dielectric's F (Schlick or exact, on the microfacet), and transmission
// (Walter et al. 2007, eq. 21) f = tint (1 - F) D G2 |wi.h| |wo.h| / (wo.z |wi.z| (wi.h + wo.h /
// eta)^2) through the generalised half vector h = normalize(wo + eta wi), eta = n(wi's side) /
// n(wo's side). No 1/eta^2 radiance scaling, as the smooth dielectric, so f(wo, wi) n(wo)^2 =
// f(wi, wo) n(wi)^2. Sampled by a visible normal, reflected with probability F, else refracted,
// each weighing G2 / G1(wo). Below kSmoothRoughness the smooth dielectric. In Whitted's model
// that smooth glass, or lit by its BRDF (no refraction).
#pragma once
#include "kernel/material/dielectric.h"
#include "kernel/shading/microfacet_bsdf.h"

namespace tracer {

struct GgxDielectricMaterial : MaterialKindBase {
  // Indices of refraction on wo's and on the other side; `front`: wo is outside.
  TRACER_HD static void sides(const Material& m, bool front, float& n_wo, float& n_other) {
    n_wo = front ? 1.0f : m.ior;
    n_other = front ? m.ior : 1.0f;
  }
  TRACER_HD static bool is_specular(const Material& m) { return is_smooth(m.roughness); }
  TRACER_HD static bool uses_choice(const Material&) { return true; }
  TRACER_HD static Vec3 albedo(const Material& m) { return m.tint; }
  // In the local frame of the shading normal (wo.z > 0).
  TRACER_HD static BsdfValue eval_local(const Material& m, Vec3 wo, Vec3 wi, bool front) {
    float n_wo, n_other;
    sides(m, front, n_wo, n_other);
    const float alpha = ggx_alpha(m.roughness);
    const BsdfValue none = {{0.0f, 0.0f, 0.0f}, 0.0f};  // also keeps exact Fresnel off cos 0 at ior 1 (0 / 0)
    if (wi.z > 0.0f) {
      const SpecularLobe r = specular_reflection(wo, wi, alpha);
      if (!(r.cos_oh > 0.0f)) return none;
      const float f = dielectric_reflectance_at(m.fresnel, r.cos_oh, n_wo, n_other);
      return {Vec3{1.0f, 1.0f, 1.0f} * (f * r.f_cos), f * r.pdf};
    }
    const SpecularLobe t = specular_transmission(wo, wi, n_other / n_wo, alpha);
    if (n_wo == n_other || !(t.cos_oh > 0.0f)) return none;  // index-matched: a delta (sample_local)
    const float f = 1.0f - dielectric_reflectance_at(m.fresnel, t.cos_oh, n_wo, n_other);
    return {m.tint * (f * t.f_cos), f * t.pdf};
  }
  TRACER_HD static bool sample_local(const Material& m, Vec3 wo, bool front, float u_choice, float u1, float u2,
                                     BsdfSample& s) {
    float n_wo, n_other;
    sides(m, front, n_wo, n_other);
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
  TRACER_HD static BsdfValue eval(const Material& m, Vec3 wo, Vec3 wi, Vec3 n, bool front) {
    const Frame f = frame_around(n);
    const Vec3 o = f.to_local(wo), i = f.to_local(wi);
    if (!(o.z > 0.0f) || is_specular(m)) return {{0.0f, 0.0f, 0.0f}, 0.0f};
    return eval_local(m, o, i, front);
  }
  TRACER_HD static bool sample(const Material& m, Vec3 wo, Vec3 n, bool front, float u_choice, float u1, float u2,
                               BsdfSample& s) {
    if (is_smooth(m.roughness)) return DielectricMaterial::sample(m, wo, n, front, u_choice, u1, u2, s);
    const Frame f = frame_around(n);
    const Vec3 o = f.to_local(wo);
    if (!(o.z > 0.0f)) return false;
    const bool ok = sample_local(m, o, front, u_choice, u1, u2, s);
    s.wi = f.to_world(s.wi);
    return ok;
  }
  TRACER_HD static WhittedResponse whitted(const Material& m, float) {
    WhittedResponse w = whitted_emission_only(m);
    if (is_smooth(m.roughness)) w.kt = m.tint, w.ior = m.ior;
    w.brdf = !is_smooth(m.roughness);
    return w;
  }
};

}  // namespace tracer
