// metal (MaterialKind::PhongMetal): roughness 0 is a mirror tinted by albedo. Otherwise a Phong
// lobe cos^e(alpha) about the mirror direction, e = 2 / roughness^2 - 2, sampled exactly, with
// f cos = albedo (e + 1) / (2 pi) cos^e(alpha): each sample weighs albedo, and lobe directions
// below the surface are absorbed. In Whitted's model a mirror tinted by albedo at any roughness.
#pragma once
#include "kernel/material/material_kind_base.h"
#include "kernel/shading/optics.h"

namespace tracer {

TRACER_HD float metal_exponent(float roughness) { return 2.0f / (roughness * roughness) - 2.0f; }

struct PhongMetalMaterial : MaterialKindBase {
  TRACER_HD static bool is_specular(const Material& m) { return m.roughness == 0.0f; }
  TRACER_HD static bool is_perfect_mirror(const Material& m) { return m.roughness == 0.0f; }
  TRACER_HD static Vec3 mirror_reflectance(const Material& m, float) { return m.albedo; }
  TRACER_HD static BsdfValue eval(const Material& m, Vec3 wo, Vec3 wi, Vec3 n, bool) {
    const float cos_i = dot(wi, n);
    BsdfValue v = {{0.0f, 0.0f, 0.0f}, 0.0f};
    if (!(cos_i > 0.0f)) return v;
    if (m.roughness == 0.0f) return v;
    v.pdf = phong_lobe_pdf(metal_exponent(m.roughness), dot(wi, reflect(-wo, n)));
    v.f_cos = m.albedo * v.pdf;
    return v;
  }
  TRACER_HD static bool sample(const Material& m, Vec3 wo, Vec3 n, bool, float, float u1, float u2, BsdfSample& s) {
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
  TRACER_HD static WhittedResponse whitted(const Material& m, float) {  // roughness has no meaning here
    WhittedResponse w = whitted_emission_only(m);
    w.kr = m.albedo;
    return w;
  }
};

}  // namespace tracer
