#include "scene/mtl_materials.h"

#include <cmath>
#include <filesystem>

#include "io/input_error.h"

namespace tracer {

Material material_from_mtl(const MtlMaterial& mtl, TextureLoader& textures, const std::string& obj_dir,
                           const std::string& where, std::string& type) {
  Material m = plain_material(MaterialKind::Lambert);
  m.ior = 1.0f;
  m.shininess = 1.0f;
  const auto file = [&](const std::string& name) { return (std::filesystem::path(obj_dir) / name).string(); };
  const std::string at = where + " (MTL material \"" + mtl.name + "\")";
  const auto colour_map = [&](const std::string& name, Vec3 constant, uint32_t& slot) {
    if (name.empty()) return constant;
    Vec3 mean;
    slot = textures.image_file(at, file(name), false, mean);
    return mean;
  };
  // tinyobjloader reads 1e999 as inf and keeps negative colours; refuse both.
  for (const auto& [name, c] : {std::pair{"Kd", mtl.kd}, std::pair{"Ks", mtl.ks}, std::pair{"Ke", mtl.ke}})
    if (!is_finite(c) || c.x < 0.0f || c.y < 0.0f || c.z < 0.0f)
      throw InputError(at + ": " + name + " must be three finite numbers >= 0");
  if (!std::isfinite(mtl.ns) || mtl.ns < 0.0f) throw InputError(at + ": Ns must be a finite number >= 0");
  if (!std::isfinite(mtl.ni)) throw InputError(at + ": Ni must be a finite number");
  if (!(mtl.d >= 0.0f && mtl.d <= 1.0f)) throw InputError(at + ": d must be in [0, 1]");
  if (max_component(mtl.ke) > 0.0f) {
    type = "emissive";
    m.kind = MaterialKind::Emissive;
    m.radiance = mtl.ke;
    m.albedo = colour_map(mtl.map_kd, mtl.kd, m.texture[kSlotAlbedo]);
  } else if (mtl.d < 1.0f) {
    type = "dielectric";
    m.kind = MaterialKind::Dielectric;
    m.ior = mtl.ni > 1.0f ? mtl.ni : 1.5f;
    m.tint = mtl.kd;
  } else if (mtl.illum == 3 && max_component(mtl.kd) == 0.0f && max_component(mtl.ks) > 0.0f) {
    type = "metal";
    m.kind = MaterialKind::PhongMetal;
    m.albedo = mtl.ks;
    m.roughness = std::min(1.0f, std::sqrt(2.0f / (std::max(mtl.ns, 0.0f) + 2.0f)));
  } else if (max_component(mtl.ks) > 0.0f) {
    type = "phong";
    m.kind = MaterialKind::Phong;
    m.albedo = colour_map(mtl.map_kd, mtl.kd, m.texture[kSlotAlbedo]);
    m.ambient = m.albedo;
    m.texture[kSlotAmbient] = m.texture[kSlotAlbedo];
    m.specular = mtl.ks;
    m.shininess = std::max(mtl.ns, 0.0f);
    Vec3 mean;
    if (!mtl.map_ks.empty()) m.factor_map = textures.image_file(at, file(mtl.map_ks), true, mean);
  } else {
    type = "lambert";
    m.kind = MaterialKind::Lambert;
    m.albedo = colour_map(mtl.map_kd, mtl.kd, m.texture[kSlotAlbedo]);
  }
  if (type == "lambert" || type == "metal" || type == "phong") {
    Vec3 mean;
    if (!mtl.norm.empty())
      m.normal_map = textures.image_file(at, file(mtl.norm), true, mean);
    else if (!mtl.map_bump.empty())
      m.bump_map = textures.image_file(at, file(mtl.map_bump), true, mean);
  }
  return m;
}

}  // namespace tracer
