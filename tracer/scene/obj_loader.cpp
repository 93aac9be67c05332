#include <tiny_obj_loader.h>

#include <filesystem>

#include "io/input_error.h"
#include "io/text_file.h"
#include "scene/mesh.h"
#include "scene/obj_text_check.h"

namespace tracer {

std::vector<MeshTriangle> load_obj(const std::string& path, const std::string& scene_file, const std::string& key_path,
                                   std::vector<MtlMaterial>* materials) {
  auto fail = [&](const std::string& message) -> void {
    throw InputError(scene_file + ": " + key_path + ": " + path + ": " + message);
  };
  if (!std::filesystem::exists(path)) fail("no such file");
  if (!std::filesystem::is_regular_file(path)) fail("not a regular file");
  check_obj_text(read_text_file(path, "OBJ file"), scene_file + ": " + key_path + ": " + path);
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // we fan-triangulate ourselves, the documented way
  config.mtl_search_path = std::filesystem::path(path).parent_path().string();
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config)) fail("malformed OBJ: " + reader.Error());
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const size_t nv = attrib.vertices.size() / 3, nn = attrib.normals.size() / 3, nt = attrib.texcoords.size() / 2;
  std::vector<MeshTriangle> out;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    size_t offset = 0;
    for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
      const size_t count = shape.mesh.num_face_vertices[f];
      if (count < 3) fail("face with fewer than 3 vertices in shape '" + shape.name + "'");
      const tinyobj::index_t* idx = &shape.mesh.indices[offset];
      for (size_t k = 0; k < count; ++k) {
        if (idx[k].vertex_index < 0 || static_cast<size_t>(idx[k].vertex_index) >= nv)
          fail("vertex index out of range in shape '" + shape.name + "'");
        if (idx[k].normal_index >= 0 && static_cast<size_t>(idx[k].normal_index) >= nn)
          fail("normal index out of range in shape '" + shape.name + "'");
        if (idx[k].texcoord_index >= 0 && static_cast<size_t>(idx[k].texcoord_index) >= nt)
          fail("texture coordinate index out of range in shape '" + shape.name + "'");
      }
      for (size_t k = 1; k + 1 < count; ++k) {
        const tinyobj::index_t corners[3] = {idx[0], idx[k], idx[k + 1]};
        MeshTriangle tri;
        tri.has_normals = tri.has_uvs = true;
        tri.mtl = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
        for (int c = 0; c < 3; ++c) {
          const int vi = corners[c].vertex_index, ni = corners[c].normal_index, ti = corners[c].texcoord_index;
          tri.p[c] = {attrib.vertices[3 * vi], attrib.vertices[3 * vi + 1], attrib.vertices[3 * vi + 2]};
          if (ni >= 0)
            tri.n[c] = {attrib.normals[3 * ni], attrib.normals[3 * ni + 1], attrib.normals[3 * ni + 2]};
          else
            tri.has_normals = false;
          if (ti >= 0) {
            tri.uv[c][0] = attrib.texcoords[2 * ti];
            tri.uv[c][1] = attrib.texcoords[2 * ti + 1];
          } else {
            tri.has_uvs = false;
          }
        }
        for (int c = 0; c < 3; ++c)
          if (!is_finite(tri.p[c]) || (tri.has_normals && !is_finite(tri.n[c])))
            fail("non-finite vertex data in shape '" + shape.name + "'");
        out.push_back(tri);
      }
      offset += count;
    }
  }
  if (out.empty()) fail("no faces");
  if (materials) {
    const auto& mtl = reader.GetMaterials();
    if (mtl.empty())
      fail("the mesh has no \"material\" and its OBJ names no MTL materials" +
           (reader.Warning().empty() ? std::string()
                                     : " (" + reader.Warning().substr(0, reader.Warning().find('\n')) + ")"));
    for (const tinyobj::material_t& m : mtl) {
      MtlMaterial out_m;
      out_m.name = m.name;
      out_m.kd = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
      out_m.ks = {m.specular[0], m.specular[1], m.specular[2]};
      out_m.ke = {m.emission[0], m.emission[1], m.emission[2]};
      out_m.ns = m.shininess;
      out_m.ni = m.ior;
      out_m.d = m.dissolve;
      out_m.illum = m.illum;
      out_m.map_kd = m.diffuse_texname;
      out_m.map_ks = m.specular_texname;
      out_m.map_bump = m.bump_texname;
      out_m.norm = m.normal_texname;
      materials->push_back(out_m);
    }
  }
  return out;
}

}  // namespace tracer
