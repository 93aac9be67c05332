// OBJ/MTL materials onto ours (docs/materials.md), for a mesh with no "material":
//   Ke > 0                          -> emissive {radiance Ke, albedo Kd}
//   d < 1 (dissolve)                -> dielectric {ior Ni (1.5 when Ni <= 1), tint Kd}
//   illum 3 and Kd = 0, Ks > 0      -> metal {albedo Ks, roughness sqrt(2 / (Ns + 2))}
//   Ks > 0                          -> phong {diffuse Kd or map_Kd, specular Ks, specular_map
//                                      map_Ks, shininess Ns}
//   otherwise                       -> lambert {albedo Kd or map_Kd}
// map_bump / bump become a bump map, norm a normal map, on lambert, metal and phong.
#pragma once
#include <string>

#include "scene/mesh.h"
#include "scene/texture_loader.h"

namespace tracer {

// `obj_dir` resolves the map file names; `where` names the scene key in errors; `type`
// receives our material type's name.
Material material_from_mtl(const MtlMaterial& mtl, TextureLoader& textures, const std::string& obj_dir,
                           const std::string& where, std::string& type);

}  // namespace tracer
