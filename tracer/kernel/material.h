// Materials as plain data: one struct for every kind, the fields a kind does not use are 0.
#pragma once
#include "vec3.h"

namespace tracer {

enum class MaterialKind : uint32_t { Lambert, Metal, Dielectric, Phong, Emissive };
enum class FresnelKind : uint32_t { Schlick, Exact };

struct Material {
  MaterialKind kind;
  FresnelKind fresnel;  // dielectric, and phong with transparency
  uint32_t two_sided;   // emissive
  float shininess;      // phong
  Vec3 albedo;          // lambert, metal; phong's diffuse colour
  Vec3 ambient;         // phong
  Vec3 specular;        // phong
  Vec3 tint;            // dielectric transmission colour
  Vec3 radiance;        // emissive
  float roughness;      // metal
  float reflectivity;   // phong
  float transparency;   // phong
  float ior;            // dielectric, phong
};

}  // namespace tracer
