// Materials as plain data: one record for every kind (the fields a kind does not use are 0),
// and the list of kinds, written once. Each kind's scattering, Whitted response and views live
// in its own header under kernel/material/ (material_kind_base.h says what each answers);
// bsdf.h dispatches on the kind.
#pragma once
#include "kernel/base/features.h"
#include "kernel/base/vec3.h"
#include "kernel/shading/texture.h"

// X(Kind, the kind's struct, its scene-file name, its feature bit), in the order of the enum's
// values (bundles store them).
#define TRACER_MATERIAL_KINDS(X)                                                  \
  X(Lambert, LambertMaterial, "lambert", kFeatureLambert)                         \
  X(PhongMetal, PhongMetalMaterial, "metal", kFeatureMetal)                       \
  X(Dielectric, DielectricMaterial, "dielectric", kFeatureDielectric)             \
  X(Phong, PhongMaterial, "phong", kFeaturePhong)                                 \
  X(Emissive, EmissiveMaterial, "emissive", kFeatureEmissive)                     \
  X(GgxConductor, GgxConductorMaterial, "conductor", kFeatureMicrofacet)          \
  X(GgxDielectric, GgxDielectricMaterial, "rough_dielectric", kFeatureMicrofacet) \
  X(GltfMetalRough, GltfMetalRoughMaterial, "metal_rough", kFeatureMicrofacet)

namespace tracer {

enum class MaterialKind : uint32_t {
#define TRACER_MATERIAL_ENUM(Kind, ...) Kind,
  TRACER_MATERIAL_KINDS(TRACER_MATERIAL_ENUM)
#undef TRACER_MATERIAL_ENUM
};
enum class FresnelKind : uint32_t { Schlick, Exact };

// How a material's alpha cuts its surface out (kernel/accel/alpha_test.h): glTF's alphaMode.
enum class AlphaMode : uint32_t {
  Opaque,  // every hit counts
  Mask,    // a hit counts where alpha >= alpha_cutoff
  Blend    // a hit counts with probability alpha (stochastic transparency)
};

// The colours of a material a texture may replace (Material::texture).
enum ColourSlot : uint32_t { kSlotAlbedo, kSlotAmbient, kSlotSpecular, kSlotTint, kSlotRadiance, kColourSlots };

struct Material {
  MaterialKind kind;
  FresnelKind fresnel;             // dielectric, rough_dielectric, phong with transparency; conductor: Schlick
                                   // from albedo as F0, or Exact from eta and k
  uint32_t two_sided;              // whether the emission leaves both sides
  float shininess;                 // phong
  Vec3 albedo;                     // lambert, metal; phong's diffuse colour; conductor's F0; metal_rough's base colour
  Vec3 ambient;                    // phong
  Vec3 specular;                   // phong
  Vec3 tint;                       // dielectric and rough_dielectric transmission colour
  Vec3 radiance;                   // emitted: emissive's; metal_rough's and lambert's added to their
                                   // reflection (glTF's emissiveFactor); 0 for a surface that does not emit
  float roughness;                 // metal; conductor, rough_dielectric, metal_rough (GGX alpha = roughness^2)
  float metallic;                  // metal_rough
  float transmission;              // metal_rough (thin-walled, KHR_materials_transmission)
  Vec3 eta, k;                     // conductor with exact Fresnel: complex index of refraction per channel
  float reflectivity;              // phong
  float transparency;              // phong
  float ior;                       // dielectric, rough_dielectric, phong, metal_rough (its F0)
  uint32_t texture[kColourSlots];  // per ColourSlot: kNoTexture, or the texture replacing it
  uint32_t factor_map;             // scales factors: phong's specular colour (the scene's specular_map);
                                   // metal_rough's roughness by G and metallic by B (glTF's
                                   // metallicRoughnessTexture); kNoTexture when absent
  uint32_t normal_map;             // tangent-space normals (2c - 1); kNoTexture when absent
  uint32_t bump_map;               // heights; kNoTexture when absent
  AlphaMode alpha_mode;            // opaque unless the scene cuts the surface out
  float alpha;                     // the alpha factor, in [0, 1]
  float alpha_cutoff;              // mask: the least alpha a hit keeps
  uint32_t alpha_map;              // alpha by texture (its first channel) times `alpha`; kNoTexture when absent
};

// A material of `kind` with no texture, map or cut-out, the other fields 0: what every reader
// starts from.
TRACER_HD Material plain_material(MaterialKind kind) {
  Material m{};
  m.kind = kind;
  for (uint32_t& t : m.texture) t = kNoTexture;
  m.factor_map = m.normal_map = m.bump_map = m.alpha_map = kNoTexture;
  m.alpha_mode = AlphaMode::Opaque;
  m.alpha = 1.0f;
  m.alpha_cutoff = 0.5f;
  return m;
}

// Whether a surface of this material emits (where its radiance texture, if any, is not black).
TRACER_HD bool emits(const Material& m) { return max_component(m.radiance) > 0.0f; }

}  // namespace tracer
