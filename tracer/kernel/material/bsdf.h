// Scattering through one dispatch on the material's kind (docs/materials.md): each operation a
// material answers (kernel/material/material_kind_base.h lists them) goes to its kind's struct,
// one header per kind, through the list of kinds in material.h. A kind outside the list (a
// damaged bundle) scatters nothing.
#pragma once
#include "kernel/material/dielectric.h"
#include "kernel/material/emissive.h"
#include "kernel/material/ggx_conductor.h"
#include "kernel/material/ggx_dielectric.h"
#include "kernel/material/gltf_metal_rough.h"
#include "kernel/material/lambert.h"
#include "kernel/material/phong.h"
#include "kernel/material/phong_metal.h"

// A case of the switch over m.kind calling the kind's TRACER_MATERIAL_OP, defined around each switch.
#define TRACER_MATERIAL_CALL(Kind, Type, ...) \
  case MaterialKind::Kind: return Type::TRACER_MATERIAL_OP;

namespace tracer {

TRACER_HD BsdfValue eval_bsdf(const Material& m, Vec3 wo, Vec3 wi, Vec3 n, bool front) {
#define TRACER_MATERIAL_OP eval(m, wo, wi, n, front)
  switch (m.kind) { TRACER_MATERIAL_KINDS(TRACER_MATERIAL_CALL) }
#undef TRACER_MATERIAL_OP
  return {{0.0f, 0.0f, 0.0f}, 0.0f};
}

// u_choice picks a lobe or Fresnel's reflect/refract; (u1, u2) the direction. False when the
// path is absorbed (a black material, a lobe direction below the surface).
TRACER_HD bool sample_bsdf(const Material& m, Vec3 wo, Vec3 n, bool front, float u_choice, float u1, float u2,
                           BsdfSample& s) {
  s.specular = false;
#define TRACER_MATERIAL_OP sample(m, wo, n, front, u_choice, u1, u2, s)
  switch (m.kind) { TRACER_MATERIAL_KINDS(TRACER_MATERIAL_CALL) }
#undef TRACER_MATERIAL_OP
  return false;
}

TRACER_HD bool is_specular(const Material& m) {
#define TRACER_MATERIAL_OP is_specular(m)
  switch (m.kind) { TRACER_MATERIAL_KINDS(TRACER_MATERIAL_CALL) }
#undef TRACER_MATERIAL_OP
  return false;
}

// Whether sample_bsdf reads u_choice; it reads (u1, u2) exactly when the material is not
// specular. The path tracer draws only the numbers read.
TRACER_HD bool bsdf_uses_choice(const Material& m) {
#define TRACER_MATERIAL_OP uses_choice(m)
  switch (m.kind) { TRACER_MATERIAL_KINDS(TRACER_MATERIAL_CALL) }
#undef TRACER_MATERIAL_OP
  return false;
}

// cos_o: the cosine between the view direction and the facing shading normal.
TRACER_HD WhittedResponse whitted_response(const Material& m, float cos_o) {
#define TRACER_MATERIAL_OP whitted(m, cos_o)
  switch (m.kind) { TRACER_MATERIAL_KINDS(TRACER_MATERIAL_CALL) }
#undef TRACER_MATERIAL_OP
  return MaterialKindBase::whitted_emission_only(m);
}

// The albedo view's colour.
TRACER_HD Vec3 material_albedo(const Material& m) {
#define TRACER_MATERIAL_OP albedo(m)
  switch (m.kind) { TRACER_MATERIAL_KINDS(TRACER_MATERIAL_CALL) }
#undef TRACER_MATERIAL_OP
  return m.albedo;
}

// Whether the material is a perfect mirror (a specular reflection alone), and what it reflects
// of light arriving at cos_theta (kernel/shading/mirror_images.h).
TRACER_HD bool is_perfect_mirror(const Material& m) {
#define TRACER_MATERIAL_OP is_perfect_mirror(m)
  switch (m.kind) { TRACER_MATERIAL_KINDS(TRACER_MATERIAL_CALL) }
#undef TRACER_MATERIAL_OP
  return false;
}
TRACER_HD Vec3 mirror_reflectance(const Material& m, float cos_theta) {
#define TRACER_MATERIAL_OP mirror_reflectance(m, cos_theta)
  switch (m.kind) { TRACER_MATERIAL_KINDS(TRACER_MATERIAL_CALL) }
#undef TRACER_MATERIAL_OP
  return {0.0f, 0.0f, 0.0f};
}

// A factor texture's value f applied to the material's parameters (Material::factor_map).
TRACER_HD void apply_factor_map(Material& m, Vec3 f) {
#define TRACER_MATERIAL_OP apply_factor_map(m, f)
  switch (m.kind) { TRACER_MATERIAL_KINDS(TRACER_MATERIAL_CALL) }
#undef TRACER_MATERIAL_OP
}

}  // namespace tracer
