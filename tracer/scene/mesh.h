// Triangles of a mesh (from an OBJ file or inline in the scene) before they become
// primitives: positions, and per-corner normals and uvs where the source has them.
#pragma once
#include <string>
#include <vector>

#include "kernel/base/vec3.h"

namespace tracer {

struct MeshTriangle {
  Vec3 p[3];
  Vec3 n[3];
  float uv[3][2];
  bool has_normals = false;
  bool has_uvs = false;
  bool has_tangents = false;  // per-vertex tangents (mesh_tangents.h)
  Vec3 tangent[3];
  float bitangent_sign = 1.0f;  // glTF's TANGENT w: the bitangent is bitangent_sign * (n x t)
  int32_t mtl = -1;             // the face's material in the OBJ's MTL file, or -1
};

// A material of an OBJ's MTL file, as written there (tracer/mtl_materials.cpp maps it).
struct MtlMaterial {
  std::string name;
  Vec3 kd, ks, ke;
  float ns = 0.0f, ni = 1.0f, d = 1.0f;
  int illum = 0;
  std::string map_kd, map_ks, map_bump, norm;  // file names relative to the OBJ
};

// Loads an OBJ file with tinyobjloader; polygons are fan-triangulated (v0, vk, vk+1).
// `key_path` names the scene key that referred to the file, for error messages.
// With `materials`, also returns the MTL materials (an error when the file names none).
std::vector<MeshTriangle> load_obj(const std::string& path, const std::string& scene_file, const std::string& key_path,
                                   std::vector<MtlMaterial>* materials = nullptr);

}  // namespace tracer
