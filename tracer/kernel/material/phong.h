// phong: the normalised modified Phong BRDF (Lafortune and Willems 1994),
// kd / pi + ks (e + 2) / (2 pi) cos^e(alpha), sampled by picking the diffuse or the specular
// lobe in proportion to their luminance. In Whitted's model its own ambient, diffuse, specular,
// reflectivity and transparency.
#pragma once
#include "kernel/material/material_kind_base.h"
#include "kernel/shading/optics.h"

namespace tracer {

struct PhongMaterial : MaterialKindBase {
  // Probability of sampling the diffuse lobe rather than the specular one.
  TRACER_HD static float diffuse_probability(const Material& m) {
    const float d = luminance(m.albedo), s = luminance(m.specular);
    return d + s > 0.0f ? d / (d + s) : 1.0f;
  }
  TRACER_HD static bool uses_choice(const Material&) { return true; }
  TRACER_HD static BsdfValue eval(const Material& m, Vec3 wo, Vec3 wi, Vec3 n, bool) {
    const float cos_i = dot(wi, n);
    BsdfValue v = {{0.0f, 0.0f, 0.0f}, 0.0f};
    if (!(cos_i > 0.0f)) return v;
    const float cos_a = dot(wi, reflect(-wo, n));
    const float power = det_pow(max_of(cos_a, 0.0f), m.shininess);
    const float lobe = (m.shininess + 2.0f) / (2.0f * kPi) * power;
    v.f_cos = m.albedo * (cos_i / kPi) + m.specular * (lobe * cos_i);
    const float pd = diffuse_probability(m);
    const float lobe_pdf = cos_a > 0.0f ? (m.shininess + 1.0f) / (2.0f * kPi) * power : 0.0f;  // phong_lobe_pdf
    v.pdf = pd * cos_i / kPi + (1.0f - pd) * lobe_pdf;
    return v;
  }
  TRACER_HD static bool sample(const Material& m, Vec3 wo, Vec3 n, bool front, float u_choice, float u1, float u2,
                               BsdfSample& s) {
    const float pd = diffuse_probability(m);
    if (!(max_component(m.albedo) > 0.0f || max_component(m.specular) > 0.0f)) return false;
    const Vec3 local = u_choice < pd ? sample_cosine_hemisphere(u1, u2) : sample_phong_lobe(m.shininess, u1, u2);
    s.wi = frame_around(u_choice < pd ? n : reflect(-wo, n)).to_world(local);
    const BsdfValue v = eval(m, wo, s.wi, n, front);
    s.pdf = v.pdf;
    if (!(s.pdf > 0.0f)) return false;
    s.weight = v.f_cos / s.pdf;
    return true;
  }
  TRACER_HD static WhittedResponse whitted(const Material& m, float) {
    WhittedResponse w = whitted_emission_only(m);
    w.ka = m.ambient;
    w.kd = m.albedo;
    w.ks = m.specular;
    w.shininess = m.shininess;
    w.kr = Vec3{1.0f, 1.0f, 1.0f} * m.reflectivity;
    w.kt = Vec3{1.0f, 1.0f, 1.0f} * m.transparency;
    w.ior = m.ior;
    return w;
  }
};

}  // namespace tracer
