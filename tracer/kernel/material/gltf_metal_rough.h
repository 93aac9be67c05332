// metal_rough (MaterialKind::GltfMetalRough): glTF 2.0's BRDF (specification, appendix B),
// mix(dielectric, metal, metallic): metal = spec Schlick(base colour), dielectric =
// fresnel_mix(F0 from ior, (1 - transmission) base / pi, spec), where the transmission
// (KHR_materials_transmission, thin-walled: no volume) is spec tinted by base, mirrored through
// the surface; Fresnel at wo.h; spec the GGX lobe of kernel/shading/microfacet_bsdf.h. Its
// roughness is never treated as smooth: it has a diffuse lobe beside the specular. Sampled by
// picking the specular, diffuse or transmission lobe (Lobes) and weighing f / the mixture's
// density. A factor map scales roughness by its G and metallic by its B
// (metallicRoughnessTexture). In Whitted's model lit by its BRDF, ambient lighting the diffuse part.
#pragma once
#include "kernel/material/material_kind_base.h"
#include "kernel/shading/microfacet_bsdf.h"

namespace tracer {

struct GltfMetalRoughMaterial : MaterialKindBase {
  // The lobe probabilities seen from wo: specular metallic + (1 - metallic) F(wo.z), the rest
  // split into diffuse and thin-walled transmission by `transmission`. F is Schlick's from air
  // into ior, whose R0 is glTF's dielectric F0 ((ior - 1) / (ior + 1))^2.
  struct Lobes {
    float specular, diffuse, transmission;
  };
  TRACER_HD static Lobes lobes(const Material& m, float cos_o) {
    const float specular = m.metallic + (1.0f - m.metallic) * fresnel_schlick(cos_o, 1.0f, m.ior);
    const float rest = 1.0f - specular;
    return {specular, rest * (1.0f - m.transmission), rest * m.transmission};
  }
  TRACER_HD static float alpha(const Material& m) { return ggx_alpha(max_of(m.roughness, kSmoothRoughness)); }
  TRACER_HD static bool uses_choice(const Material&) { return true; }
  TRACER_HD static void apply_factor_map(Material& m, Vec3 f) {
    m.roughness = m.roughness * f.y;
    m.metallic = m.metallic * f.z;
  }
  // In the local frame of the shading normal (wo.z > 0).
  TRACER_HD static BsdfValue eval_local(const Material& m, Vec3 wo, Vec3 wi) {
    const bool transmitted = wi.z < 0.0f;
    const Vec3 wr = {wi.x, wi.y, abs_of(wi.z)};  // the thin-walled transmission mirrors the reflection
    const SpecularLobe r = specular_reflection(wo, wr, alpha(m));
    const Lobes p = lobes(m, wo.z);
    const float fd = fresnel_schlick(r.cos_oh, 1.0f, m.ior);
    if (transmitted)
      return {m.albedo * ((1.0f - m.metallic) * (1.0f - fd) * m.transmission * r.f_cos), p.transmission * r.pdf};
    if (!(wi.z > 0.0f)) return {{0.0f, 0.0f, 0.0f}, 0.0f};
    const Vec3 metal = fresnel_schlick_f0(m.albedo, r.cos_oh) * r.f_cos;
    const Vec3 dielectric =
        m.albedo * ((1.0f - fd) * (1.0f - m.transmission) * wi.z / kPi) + Vec3{1.0f, 1.0f, 1.0f} * (fd * r.f_cos);
    return {dielectric * (1.0f - m.metallic) + metal * m.metallic, p.specular * r.pdf + p.diffuse * wi.z / kPi};
  }
  TRACER_HD static bool sample_local(const Material& m, Vec3 wo, float u_choice, float u1, float u2, BsdfSample& s) {
    const Lobes p = lobes(m, wo.z);
    if (u_choice < p.specular || u_choice >= 1.0f - p.transmission) {
      s.wi = reflect_about(wo, sample_visible_normal(wo, alpha(m), u1, u2));
      if (!(s.wi.z > 0.0f)) return false;
      if (!(u_choice < p.specular)) s.wi.z = -s.wi.z;
    } else {
      s.wi = sample_cosine_hemisphere(u1, u2);
    }
    const BsdfValue v = eval_local(m, wo, s.wi);
    s.pdf = v.pdf;
    if (!(s.pdf > 0.0f)) return false;
    s.weight = v.f_cos / s.pdf;
    return true;
  }
  TRACER_HD static BsdfValue eval(const Material& m, Vec3 wo, Vec3 wi, Vec3 n, bool) {
    const Frame f = frame_around(n);
    const Vec3 o = f.to_local(wo), i = f.to_local(wi);
    if (!(o.z > 0.0f)) return {{0.0f, 0.0f, 0.0f}, 0.0f};
    return eval_local(m, o, i);
  }
  TRACER_HD static bool sample(const Material& m, Vec3 wo, Vec3 n, bool, float u_choice, float u1, float u2,
                               BsdfSample& s) {
    const Frame f = frame_around(n);
    const Vec3 o = f.to_local(wo);
    if (!(o.z > 0.0f)) return false;
    const bool ok = sample_local(m, o, u_choice, u1, u2, s);
    s.wi = f.to_world(s.wi);
    return ok;
  }
  TRACER_HD static WhittedResponse whitted(const Material& m, float) {
    WhittedResponse w = whitted_emission_only(m);
    w.ka = m.albedo * ((1.0f - m.metallic) * (1.0f - m.transmission));
    w.brdf = true;
    return w;
  }
};

}  // namespace tracer
