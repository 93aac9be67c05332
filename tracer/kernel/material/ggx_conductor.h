// conductor (MaterialKind::GgxConductor): a GGX microfacet metal (kernel/shading/microfacet.h),
// f = F(wo.h) D(h) G2 / (4 wo.z wi.z), h = normalize(wo + wi); F is Schlick's with albedo as F0,
// or the exact conductor Fresnel of eta + i k. Sampled by reflecting a visible normal, weighing
// F G2 / G1(wo). Below kSmoothRoughness a mirror tinted by its Fresnel reflectance. In Whitted's
// model that mirror, or lit by its BRDF.
#pragma once
#include "kernel/material/material_kind_base.h"
#include "kernel/shading/microfacet_bsdf.h"

namespace tracer {

TRACER_HD Vec3 conductor_fresnel(const Material& m, float cos_oh) {
  return m.fresnel == FresnelKind::Exact ? fresnel_conductor(cos_oh, m.eta, m.k) : fresnel_schlick_f0(m.albedo, cos_oh);
}

struct GgxConductorMaterial : MaterialKindBase {
  TRACER_HD static bool is_specular(const Material& m) { return is_smooth(m.roughness); }
  TRACER_HD static bool is_perfect_mirror(const Material& m) { return is_smooth(m.roughness); }
  TRACER_HD static Vec3 mirror_reflectance(const Material& m, float cos_theta) {
    return conductor_fresnel(m, cos_theta);
  }
  TRACER_HD static BsdfValue eval(const Material& m, Vec3 wo, Vec3 wi, Vec3 n, bool) {
    const Frame f = frame_around(n);
    const Vec3 o = f.to_local(wo), i = f.to_local(wi);
    if (!(o.z > 0.0f) || is_specular(m)) return {{0.0f, 0.0f, 0.0f}, 0.0f};
    const SpecularLobe r = specular_reflection(o, i, ggx_alpha(m.roughness));
    return {conductor_fresnel(m, r.cos_oh) * r.f_cos, r.pdf};
  }
  TRACER_HD static bool sample(const Material& m, Vec3 wo, Vec3 n, bool, float, float u1, float u2, BsdfSample& s) {
    if (is_smooth(m.roughness)) {
      s = {reflect(-wo, n), conductor_fresnel(m, dot(wo, n)), 0.0f, true};
      return true;
    }
    const Frame f = frame_around(n);
    const Vec3 o = f.to_local(wo);
    if (!(o.z > 0.0f)) return false;
    const float alpha = ggx_alpha(m.roughness);
    const Vec3 h = sample_visible_normal(o, alpha, u1, u2);
    s.wi = reflect_about(o, h);
    bool ok = false;
    if (s.wi.z > 0.0f) {
      s.weight = conductor_fresnel(m, dot(o, h)) * (ggx_g2(o, s.wi, alpha) / ggx_g1(o, alpha));
      s.pdf = ggx_visible_normal_pdf(o, h, alpha) / (4.0f * dot(o, h));
      ok = s.pdf > 0.0f;
    }
    s.wi = f.to_world(s.wi);
    return ok;
  }
  TRACER_HD static WhittedResponse whitted(const Material& m, float cos_o) {
    WhittedResponse w = whitted_emission_only(m);
    if (is_smooth(m.roughness)) w.kr = conductor_fresnel(m, cos_o);
    w.brdf = !is_smooth(m.roughness);
    return w;
  }
};

}  // namespace tracer
