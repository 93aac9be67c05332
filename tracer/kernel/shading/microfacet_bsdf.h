// The GGX lobes the microfacet materials are made of (kernel/material/ggx_conductor.h,
// ggx_dielectric.h, gltf_metal_rough.h), on the distribution of microfacet.h, in the local frame
// of the shading normal turned to wo's side (+z, wo.z > 0). Values are f(wo, wi) |wi.z| with
// their densities, without the Fresnel factor each material applies.
#pragma once
#include "kernel/shading/bsdf_sample.h"
#include "kernel/shading/microfacet.h"
#include "kernel/shading/optics.h"
#include "kernel/shading/sampling.h"

namespace tracer {

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

}  // namespace tracer
