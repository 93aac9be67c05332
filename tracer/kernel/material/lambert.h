// lambert: f = albedo / pi, cosine-weighted sampling.
#pragma once
#include "kernel/material/material_kind_base.h"

namespace tracer {

struct LambertMaterial : MaterialKindBase {
  TRACER_HD static BsdfValue eval(const Material& m, Vec3, Vec3 wi, Vec3 n, bool) {
    const float cos_i = dot(wi, n);
    BsdfValue v = {{0.0f, 0.0f, 0.0f}, 0.0f};
    if (!(cos_i > 0.0f)) return v;
    v.f_cos = m.albedo * (cos_i / kPi);
    v.pdf = cos_i / kPi;
    return v;
  }
  TRACER_HD static bool sample(const Material& m, Vec3, Vec3 n, bool, float, float u1, float u2, BsdfSample& s) {
    if (!(max_component(m.albedo) > 0.0f)) return false;
    const Vec3 local = sample_cosine_hemisphere(u1, u2);
    s.wi = frame_around(n).to_world(local);
    s.pdf = local.z / kPi;
    s.weight = m.albedo;
    return local.z > 0.0f;
  }
  TRACER_HD static WhittedResponse whitted(const Material& m, float) {
    WhittedResponse w = whitted_emission_only(m);
    w.ka = m.albedo;
    w.kd = m.albedo;
    return w;
  }
};

}  // namespace tracer
