// Triangles of a mesh (from an OBJ file or inline in the scene) before they become
// primitives: positions, and per-corner normals and uvs where the source has them.
#pragma once
#include <string>
#include <vector>

#include "kernel/vec3.h"

namespace tracer {

struct MeshTriangle {
  Vec3 p[3];
  Vec3 n[3];
  float uv[3][2];
  bool has_normals = false;
  bool has_uvs = false;
};

// Loads an OBJ file with tinyobjloader; polygons are fan-triangulated (v0, vk, vk+1).
// `key_path` names the scene key that referred to the file, for error messages.
std::vector<MeshTriangle> load_obj(const std::string& path, const std::string& scene_file,
                                   const std::string& key_path);

}  // namespace tracer
