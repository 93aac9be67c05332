// Materials as plain data: one struct for every kind, the fields a kind does not use are 0.
#pragma once
#include "kernel/base/vec3.h"
#include "kernel/shading/texture.h"

namespace tracer {

enum class MaterialKind : uint32_t { Lambert, Metal, Dielectric, Phong, Emissive };
enum class FresnelKind : uint32_t { Schlick, Exact };

// The colours of a material a texture may replace (Material::texture).
enum ColourSlot : uint32_t { kSlotAlbedo, kSlotAmbient, kSlotSpecular, kSlotTint, kSlotRadiance, kColourSlots };

struct Material {
  MaterialKind kind;
  FresnelKind fresnel;             // dielectric, and phong with transparency
  uint32_t two_sided;              // emissive
  float shininess;                 // phong
  Vec3 albedo;                     // lambert, metal; phong's diffuse colour
  Vec3 ambient;                    // phong
  Vec3 specular;                   // phong
  Vec3 tint;                       // dielectric transmission colour
  Vec3 radiance;                   // emissive
  float roughness;                 // metal
  float reflectivity;              // phong
  float transparency;              // phong
  float ior;                       // dielectric, phong
  uint32_t texture[kColourSlots];  // per ColourSlot: kNoTexture, or the texture replacing it
  uint32_t specular_map;           // phong: scales specular; kNoTexture when absent
  uint32_t normal_map;             // tangent-space normals (2c - 1); kNoTexture when absent
  uint32_t bump_map;               // heights; kNoTexture when absent
};

}  // namespace tracer
