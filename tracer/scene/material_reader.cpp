#include "scene/material_reader.h"

#include "kernel/base/features.h"
#include "options/enum_names.h"
#include "scene/scene_types.h"

namespace tracer {

Material read_material(const Json& value, const std::string& path, const std::string& file, std::string& type,
                       TextureLoader& textures) {
  JsonObject obj(value, path, file);
  Material m{};
  m.ior = 1.0f;
  m.shininess = 1.0f;
  for (uint32_t& t : m.texture) t = kNoTexture;
  m.specular_map = m.normal_map = m.bump_map = kNoTexture;
  type = read_type(obj, "material");
  if (type == "lambert") {
    m.kind = MaterialKind::Lambert;
    m.albedo = textures.colour(obj, "albedo", m.texture[kSlotAlbedo]);
  } else if (type == "metal") {
    m.kind = MaterialKind::Metal;
    m.albedo = textures.colour(obj, "albedo", m.texture[kSlotAlbedo]);
    m.roughness = obj.number_or("roughness", 0.0f);
    if (!(m.roughness >= 0.0f && m.roughness <= 1.0f)) obj.fail("roughness", "must be in [0, 1]");
  } else if (type == "dielectric") {
    m.kind = MaterialKind::Dielectric;
    m.ior = obj.number("ior");
    if (!(m.ior > 0.0f)) obj.fail("ior", "must be > 0");
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
    m.reflectivity = obj.number_or("reflectivity", 0.0f);
    if (!(m.reflectivity >= 0.0f && m.reflectivity <= 1.0f)) obj.fail("reflectivity", "must be in [0, 1]");
    m.transparency = obj.number_or("transparency", 0.0f);
    if (!(m.transparency >= 0.0f && m.transparency <= 1.0f)) obj.fail("transparency", "must be in [0, 1]");
    m.ior = obj.number_or("ior", 1.0f);
    if (!(m.ior > 0.0f)) obj.fail("ior", "must be > 0");
    m.specular_map = textures.data_map(obj, "specular_map");
  } else if (type == "emissive") {
    m.kind = MaterialKind::Emissive;
    m.radiance = textures.colour(obj, "radiance", m.texture[kSlotRadiance]);
    m.two_sided = obj.boolean_or("two_sided", false) ? 1u : 0u;
    m.albedo =
        textures.colour_or(obj, "albedo", {0.0f, 0.0f, 0.0f}, m.texture[kSlotAlbedo]);  // an emitter that also reflects
  }
  if (type != "dielectric" && type != "emissive") {  // surfaces with a diffuse or glossy response
    m.normal_map = textures.data_map(obj, "normal_map");
    m.bump_map = textures.data_map(obj, "bump_map");
    if (m.normal_map != kNoTexture && m.bump_map != kNoTexture)
      obj.fail("bump_map", "give a normal_map or a bump_map, not both");
  }
  obj.finish();
  return m;
}

uint32_t material_feature(MaterialKind kind) {
  switch (kind) {
    case MaterialKind::Lambert: return kFeatureLambert;
    case MaterialKind::Metal: return kFeatureMetal;
    case MaterialKind::Dielectric: return kFeatureDielectric;
    case MaterialKind::Phong: return kFeaturePhong;
    case MaterialKind::Emissive: return kFeatureEmissive;
  }
  return 0;
}

}  // namespace tracer
