// dielectric: smooth glass. Reflection or refraction chosen by the Fresnel reflectance (Schlick
// or exact), total internal reflection always reflects; refraction is tinted. Both choices are
// deltas. In Whitted's model the same split, traced as two rays.
#pragma once
#include "kernel/material/material_kind_base.h"
#include "kernel/shading/optics.h"

namespace tracer {

struct DielectricMaterial : MaterialKindBase {
  TRACER_HD static bool is_specular(const Material&) { return true; }
  TRACER_HD static bool uses_choice(const Material&) { return true; }
  TRACER_HD static Vec3 albedo(const Material& m) { return m.tint; }
  TRACER_HD static BsdfValue eval(const Material&, Vec3, Vec3, Vec3, bool) { return {{0.0f, 0.0f, 0.0f}, 0.0f}; }
  TRACER_HD static bool sample(const Material& m, Vec3 wo, Vec3 n, bool front, float u_choice, float, float,
                               BsdfSample& s) {
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
  TRACER_HD static WhittedResponse whitted(const Material& m, float) {
    WhittedResponse w = whitted_emission_only(m);
    w.kt = m.tint;
    w.ior = m.ior;
    return w;
  }
};

}  // namespace tracer
