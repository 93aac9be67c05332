#include "scene/material_reader.h"

#include <optional>

#include "kernel/base/features.h"
#include "kernel/shading/optics.h"
#include "options/enum_names.h"
#include "scene/scene_types.h"

namespace tracer {

namespace {

float unit_interval(JsonObject& obj, const std::string& key, float fallback) {
  const float x = obj.number_or(key, fallback);
  if (!(x >= 0.0f && x <= 1.0f)) obj.fail(key, "must be in [0, 1]");
  return x;
}

// The range of an index of refraction (a dielectric's ior, a conductor's eta) and of a
// conductor's extinction k. Real materials lie well inside (ior 1 to 4, relative indices 1/4
// to 4; measured metals' eta 0.03 to 30, k under 100); outside, Fresnel's squares and 1 / ior
// leave float's range (a denormal ior refracts rays of NaN direction; an eta or k past 4e9
// gives NaN reflectance).
constexpr float kMinIor = 0.01f, kMaxIor = 100.0f, kMaxExtinction = 1000.0f;

bool ior_in_range(float x) { return x >= kMinIor && x <= kMaxIor; }

// An index of refraction: required, or `fallback` when absent.
float ranged_ior(JsonObject& obj, std::optional<float> fallback) {
  const float x = fallback ? obj.number_or("ior", *fallback) : obj.number("ior");
  if (!ior_in_range(x)) obj.fail("ior", "must be in [0.01, 100]");
  return x;
}

// A conductor's Fresnel reflectance: `albedo` as F0 (Schlick), or the complex index
// `eta` + i `k` (exact), one of the two.
void read_conductor_fresnel(JsonObject& obj, TextureLoader& textures, Material& m) {
  const bool has_eta = obj.find("eta") != nullptr, has_k = obj.find("k") != nullptr;
  if (has_eta != has_k) obj.fail(has_eta ? "k" : "eta", "give both eta and k (the complex index of refraction)");
  if (!has_eta) {
    m.fresnel = FresnelKind::Schlick;
    m.albedo = textures.colour(obj, "albedo", m.texture[kSlotAlbedo]);
    if (!(max_component(m.albedo) <= 1.0f))
      obj.fail("albedo", "must be in [0, 1] (the reflectance at normal incidence)");
    return;
  }
  if (obj.find("albedo")) obj.fail("albedo", "give albedo (Schlick's F0) or eta and k, not both");
  m.fresnel = FresnelKind::Exact;
  m.eta = obj.vec3("eta");
  m.k = obj.vec3("k");
  if (!(ior_in_range(m.eta.x) && ior_in_range(m.eta.y) && ior_in_range(m.eta.z)))
    obj.fail("eta", "must be in [0.01, 100]");
  if (!(m.k.x >= 0.0f && m.k.y >= 0.0f && m.k.z >= 0.0f && max_component(m.k) <= kMaxExtinction))
    obj.fail("k", "must be in [0, 1000]");
  m.albedo = fresnel_conductor(1.0f, m.eta, m.k);  // what the albedo view shows
}

// The cut-out keys any material may have (docs/scene-format.md): alpha_mode opaque (the
// default), mask or blend; alpha in [0, 1], default 1; alpha_cutoff in [0, 1], default 0.5;
// alpha_map, an image whose alpha channel (else its first) scales alpha.
void read_alpha(JsonObject& obj, TextureLoader& textures, Material& m) {
  m.alpha_mode =
      parse_enum<AlphaMode>(obj.string_or("alpha_mode", "opaque"), obj.file() + ": " + obj.child("alpha_mode"));
  m.alpha = unit_interval(obj, "alpha", 1.0f);
  m.alpha_cutoff = unit_interval(obj, "alpha_cutoff", 0.5f);
  m.alpha_map = obj.find("alpha_map")
                    ? textures.alpha_map(obj.child("alpha_map"), textures.resolve(obj.string("alpha_map")))
                    : kNoTexture;
  if (m.alpha_mode == AlphaMode::Opaque)
    for (const char* key : {"alpha", "alpha_cutoff", "alpha_map"})
      if (obj.find(key)) obj.fail(key, "needs \"alpha_mode\": \"mask\" or \"blend\" (an opaque surface has no alpha)");
}

}  // namespace

Material read_material(const Json& value, const std::string& path, const std::string& file, std::string& type,
                       TextureLoader& textures) {
  JsonObject obj(value, path, file);
  Material m = plain_material(MaterialKind::Lambert);
  m.ior = 1.0f;
  m.shininess = 1.0f;
  type = read_type(obj, "material");
  if (type == "lambert") {
    m.kind = MaterialKind::Lambert;
    m.albedo = textures.colour(obj, "albedo", m.texture[kSlotAlbedo]);
  } else if (type == "metal") {
    m.kind = MaterialKind::PhongMetal;
    m.albedo = textures.colour(obj, "albedo", m.texture[kSlotAlbedo]);
    m.roughness = unit_interval(obj, "roughness", 0.0f);
  } else if (type == "dielectric") {
    m.kind = MaterialKind::Dielectric;
    m.ior = ranged_ior(obj, std::nullopt);
    m.tint = textures.colour_or(obj, "tint", {1.0f, 1.0f, 1.0f}, m.texture[kSlotTint]);
    m.fresnel = parse_enum<FresnelKind>(obj.string_or("fresnel", "schlick"), file + ": " + obj.child("fresnel"));
  } else if (type == "phong") {
    m.kind = MaterialKind::Phong;
    m.albedo = textures.colour(obj, "diffuse", m.texture[kSlotAlbedo]);
    m.ambient = textures.colour_or(obj, "ambient", m.albedo, m.texture[kSlotAmbient]);
    if (!obj.find("ambient")) m.texture[kSlotAmbient] = m.texture[kSlotAlbedo];  // ambient follows diffuse
    m.specular = textures.colour_or(obj, "specular", {0.0f, 0.0f, 0.0f}, m.texture[kSlotSpecular]);
    m.shininess = obj.number_or("shininess", 1.0f);
    if (!(m.shininess >= 0.0f)) obj.fail("shininess", "must be >= 0");
    m.reflectivity = unit_interval(obj, "reflectivity", 0.0f);
    m.transparency = unit_interval(obj, "transparency", 0.0f);
    m.ior = ranged_ior(obj, 1.0f);
    m.factor_map = textures.data_map(obj, "specular_map");
  } else if (type == "conductor") {
    m.kind = MaterialKind::GgxConductor;
    read_conductor_fresnel(obj, textures, m);
    m.roughness = unit_interval(obj, "roughness", 0.0f);
  } else if (type == "rough_dielectric") {
    m.kind = MaterialKind::GgxDielectric;
    m.ior = ranged_ior(obj, std::nullopt);
    m.roughness = unit_interval(obj, "roughness", 0.0f);
    m.tint = textures.colour_or(obj, "tint", {1.0f, 1.0f, 1.0f}, m.texture[kSlotTint]);
    m.fresnel = parse_enum<FresnelKind>(obj.string_or("fresnel", "schlick"), file + ": " + obj.child("fresnel"));
  } else if (type == "metal_rough") {
    m.kind = MaterialKind::GltfMetalRough;
    m.albedo = textures.colour(obj, "base_color", m.texture[kSlotAlbedo]);
    if (!(max_component(m.albedo) <= 1.0f)) obj.fail("base_color", "must be in [0, 1]");
    m.metallic = unit_interval(obj, "metallic", 0.0f);
    m.roughness = unit_interval(obj, "roughness", 1.0f);
    m.transmission = unit_interval(obj, "transmission", 0.0f);
    m.ior = ranged_ior(obj, 1.5f);
  } else if (type == "emissive") {
    m.kind = MaterialKind::Emissive;
    m.radiance = textures.colour(obj, "radiance", m.texture[kSlotRadiance]);
    m.two_sided = obj.boolean_or("two_sided", false) ? 1u : 0u;
    m.albedo =
        textures.colour_or(obj, "albedo", {0.0f, 0.0f, 0.0f}, m.texture[kSlotAlbedo]);  // an emitter that also reflects
  }
  if (type != "dielectric" && type != "rough_dielectric" &&
      type != "emissive") {  // surfaces with a diffuse or glossy response
    m.normal_map = textures.data_map(obj, "normal_map");
    m.bump_map = textures.data_map(obj, "bump_map");
    if (m.normal_map != kNoTexture && m.bump_map != kNoTexture)
      obj.fail("bump_map", "give a normal_map or a bump_map, not both");
  }
  read_alpha(obj, textures, m);
  obj.finish();
  return m;
}

uint32_t material_feature(MaterialKind kind) {
  switch (kind) {
#define TRACER_MATERIAL_FEATURE(Kind, Type, name, feature) \
  case MaterialKind::Kind: return feature;
    TRACER_MATERIAL_KINDS(TRACER_MATERIAL_FEATURE)
#undef TRACER_MATERIAL_FEATURE
  }
  return 0;
}

}  // namespace tracer
