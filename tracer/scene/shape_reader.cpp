#include "scene/shape_reader.h"

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "scene/material_reader.h"
#include "io/text_file.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_scene.h"
#include "scene/mesh.h"
#include "scene/mesh_primitives.h"
#include "scene/mtl_materials.h"
#include "scene/scene_types.h"
#include "scene/transform.h"

namespace tracer {
namespace {

// Also records each step's kind in `used_types` ("transform:rotate").
Transform read_transform(const Json& value, const std::string& path, const std::string& file,
                         std::set<std::string>& used_types) {
  if (!value.is_array()) fail_at(file, path, "expected an array of transform steps, got " + describe(value));
  Transform total;
  for (size_t i = 0; i < value.size(); ++i) {
    const std::string item_path = path + "[" + std::to_string(i) + "]";
    JsonObject step(value[i], item_path, file);
    if (value[i].size() != 1 || !is_accepted_type("transform", value[i].begin().key()))
      step.fail("", "each step has exactly one of " + expected_types("transform"));
    used_types.insert("transform:" + value[i].begin().key());
    Transform t;
    if (step.find("translate")) {
      t = Transform::translation(step.vec3("translate"));
    } else if (const Json* s = step.find("scale")) {
      const Vec3 f = s->is_number() ? Vec3{1, 1, 1} * read_number(*s, step.child("scale"), file) : step.vec3("scale");
      if (f.x == 0.0f || f.y == 0.0f || f.z == 0.0f) step.fail("scale", "a scale factor of 0 collapses the shape");
      t = Transform::scaling(f);
    } else if (step.find("rotate")) {
      JsonObject rot(step.get("rotate"), step.child("rotate"), file);
      const Vec3 axis = rot.vec3("axis");
      if (length(axis) == 0.0f) rot.fail("axis", "the rotation axis must not be zero");
      t = Transform::rotation(axis, rot.number("degrees"));
      rot.finish();
    } else if (step.find("rotate_xyz")) {
      const Vec3 deg = step.vec3("rotate_xyz");
      t = Transform::rotation({1, 0, 0}, deg.x)
              .then(Transform::rotation({0, 1, 0}, deg.y))
              .then(Transform::rotation({0, 0, 1}, deg.z));
    }
    step.finish();
    total = total.then(t);
  }
  return total;
}

class ShapeReader {
 public:
  ShapeReader(Scene& scene, const std::string& dir, TextureLoader& textures)
      : scene_(scene), dir_(dir), textures_(textures) {}

  void add_shape(const Json& value, const std::string& path, const std::map<std::string, uint32_t>& material_ids,
                 const std::vector<std::string>& material_types) {
    JsonObject obj(value, path, scene_.file);
    const std::string type = obj.string("type");
    if (!is_accepted_type("shape", type))
      obj.fail("type", "unknown shape type \"" + type + "\" (expected " + expected_types("shape") + ")");
    const Json* tv = obj.find("transform");
    const Transform xf =
        tv ? read_transform(*tv, obj.child("transform"), scene_.file, scene_.report.used_types) : Transform{};
    if (type == "gltf") return add_gltf(obj, xf);
    const Json* mat = obj.find("material");
    if (!mat && type == "mesh" && obj.find("file")) return add_mtl_mesh(obj, xf);
    if (!mat)
      obj.fail("material", type == "mesh" ? "missing: give the mesh a \"material\", or a file whose MTL has them"
                                          : "missing required key");
    if (!mat->is_string()) obj.fail("material", "expected a material name, got " + describe(*mat));
    const auto it = material_ids.find(mat->get<std::string>());
    if (it == material_ids.end()) obj.fail("material", "unknown material \"" + mat->get<std::string>() + "\"");
    const uint32_t material = it->second;

    if (type == "sphere") {
      const float radius = obj.number("radius");
      if (!(radius > 0.0f)) obj.fail("radius", "must be > 0");
      if (!xf.uniform_scale) obj.fail("transform", "a sphere takes only uniform scales");
      add({ShapeKind::Sphere, material, -1, radius * xf.scale, xf.point(obj.vec3("center")), {}, {}});
    } else if (type == "plane") {
      const Vec3 n = obj.vec3("normal");
      if (length(n) == 0.0f) obj.fail("normal", "must not be zero");
      add({ShapeKind::Plane, material, -1, 0.0f, xf.point(obj.vec3("point")), xf.normal(normalize(n)), {}});
    } else if (type == "quad") {
      add_quad(obj, xf.point(obj.vec3("corner")), xf.vector(obj.vec3("u")), xf.vector(obj.vec3("v")), material);
    } else if (type == "box") {
      const Vec3 lo = obj.vec3("min"), hi = obj.vec3("max");
      if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z)) obj.fail("max", "must exceed min on every axis");
      add_box(obj, lo, hi, xf, material);
    } else if (type == "triangle") {
      add_triangles(obj, {inline_triangle(obj)}, xf, {material});
    } else if (type == "mesh") {
      if (obj.find("file")) {
        const std::string rel = obj.string("file");
        for (const char* k : {"positions", "indices", "normals", "uvs"})
          if (obj.find(k)) obj.fail(k, "a mesh has either \"file\" or inline data, not both");
        const std::string path = (std::filesystem::path(dir_) / rel).string();
        scene_.report.input_files.insert(path);
        const auto tris = load_obj(path, scene_.file, obj.child("file"));
        add_triangles(obj, tris, xf, std::vector<uint32_t>(tris.size(), material));
      } else {
        const auto tris = inline_mesh(obj);
        add_triangles(obj, tris, xf, std::vector<uint32_t>(tris.size(), material));
      }
    }
    obj.finish();
    ++scene_.report.shape_counts[type];
    scene_.report.used_types.insert("shape:" + type);
    scene_.report.used_types.insert("material:" + material_types[material]);
  }

 private:
  // A mesh whose faces take the materials of its OBJ's MTL file (mtl_materials.h); faces
  // with no usemtl get a grey lambert.
  void add_mtl_mesh(JsonObject& obj, const Transform& xf) {
    const std::filesystem::path file = std::filesystem::path(dir_) / obj.string("file");
    for (const char* k : {"positions", "indices", "normals", "uvs"})
      if (obj.find(k)) obj.fail(k, "a mesh has either \"file\" or inline data, not both");
    std::vector<MtlMaterial> mtls;
    scene_.report.input_files.insert(file.string());
    const auto tris = load_obj(file.string(), scene_.file, obj.child("file"), &mtls);
    const uint32_t base = static_cast<uint32_t>(scene_.materials.size());
    for (const MtlMaterial& mtl : mtls) {
      std::string type;
      scene_.materials.push_back(
          material_from_mtl(mtl, textures_, file.parent_path().string(), obj.child("file"), type));
      scene_.material_names.push_back(file.filename().string() + ":" + mtl.name);
      scene_.report.used_types.insert("material:" + type);
    }
    Material grey{};
    grey.kind = MaterialKind::Lambert;
    grey.albedo = {0.5f, 0.5f, 0.5f};
    for (uint32_t& t : grey.texture) t = kNoTexture;
    grey.factor_map = grey.normal_map = grey.bump_map = kNoTexture;
    const uint32_t fallback = static_cast<uint32_t>(scene_.materials.size());
    scene_.materials.push_back(grey);
    scene_.material_names.push_back(file.filename().string() + ":(no usemtl)");
    std::vector<uint32_t> materials;
    for (const MeshTriangle& t : tris) materials.push_back(t.mtl >= 0 ? base + static_cast<uint32_t>(t.mtl) : fallback);
    add_triangles(obj, tris, xf, materials);
    obj.finish();
    ++scene_.report.shape_counts["mesh"];
    scene_.report.used_types.insert("shape:mesh");
  }

  // A glTF file's meshes with their own materials (docs/gltf.md): its lights and cameras are
  // left to the scene file. Its errors name the glTF file and the JSON path inside it.
  void add_gltf(JsonObject& obj, const Transform& xf) {
    if (obj.find("material")) obj.fail("material", "a gltf shape takes its file's materials");
    const std::string file = (std::filesystem::path(dir_) / obj.string("file")).string();
    scene_.report.input_files.insert(file);
    try {
      std::error_code ec;
      std::unique_ptr<PlacedGltf>& placed = gltf_files_[std::filesystem::weakly_canonical(file, ec).string()];
      if (!placed) placed = std::make_unique<PlacedGltf>(
                       read_gltf_file(read_text_file(file, "glTF file", kMaxGltfFileBytes), file), scene_);
      const GltfContents contents = add_gltf_file(placed->file, xf, false, scene_, placed->materials);
      if (contents.triangles == 0) obj.fail("file", "its default scene places no triangles");
      for (const std::string& s : contents.ignored) scene_.report.gltf.push_back(file + ": ignored " + s);
    } catch (const InputError& e) {
      fail_at(scene_.file, obj.child("file"), e.what());
    }
    obj.finish();
    ++scene_.report.shape_counts["gltf"];
    scene_.report.used_types.insert("shape:gltf");
  }

  void add(const Primitive& p) { append_primitive(scene_, p); }

  void add_quad(JsonObject& obj, Vec3 corner, Vec3 u, Vec3 v, uint32_t material) {
    if (!has_unit_normal(u, v))
      obj.fail("", "zero-area quad (u and v are parallel or zero, or its normal under- or overflows a float)");
    add({ShapeKind::Quad, material, -1, 0.0f, corner, u, v});
  }

  void add_box(JsonObject& obj, Vec3 lo, Vec3 hi, const Transform& xf, uint32_t material) {
    const Vec3 dx = {hi.x - lo.x, 0, 0}, dy = {0, hi.y - lo.y, 0}, dz = {0, 0, hi.z - lo.z};
    // Six faces with outward normals cross(u, v).
    const Vec3 faces[6][3] = {{lo, dx, dz}, {lo, dy, dx}, {lo, dz, dy}, {hi, -dz, -dx}, {hi, -dx, -dy}, {hi, -dy, -dz}};
    for (const auto& f : faces) add_quad(obj, xf.point(f[0]), xf.vector(f[1]), xf.vector(f[2]), material);
  }

  MeshTriangle inline_triangle(JsonObject& obj) {
    const Json& vs = obj.get("vertices");
    if (!vs.is_array() || vs.size() != 3) obj.fail("vertices", "expected 3 vertices, got " + describe(vs));
    MeshTriangle t;
    for (int i = 0; i < 3; ++i)
      t.p[i] = read_vec3(vs[i], obj.child("vertices") + "[" + std::to_string(i) + "]", scene_.file);
    if (const Json* ns = obj.find("normals")) {
      if (!ns->is_array() || ns->size() != 3) obj.fail("normals", "expected 3 normals, got " + describe(*ns));
      for (int i = 0; i < 3; ++i)
        t.n[i] = read_vec3((*ns)[i], obj.child("normals") + "[" + std::to_string(i) + "]", scene_.file);
      t.has_normals = true;
    }
    if (const Json* uvs = obj.find("uvs")) {
      if (!uvs->is_array() || uvs->size() != 3) obj.fail("uvs", "expected 3 uv pairs, got " + describe(*uvs));
      read_uvs(*uvs, obj.child("uvs"), [&](size_t i, float u, float v) {
        t.uv[i][0] = u;
        t.uv[i][1] = v;
      });
      t.has_uvs = true;
    }
    return t;
  }

  template <class F>
  void read_uvs(const Json& uvs, const std::string& path, F store) {
    for (size_t i = 0; i < uvs.size(); ++i) {
      const std::string p = path + "[" + std::to_string(i) + "]";
      if (!uvs[i].is_array() || uvs[i].size() != 2) fail_at(scene_.file, p, "expected [u, v], got " + describe(uvs[i]));
      store(i, read_number(uvs[i][0], p + "[0]", scene_.file), read_number(uvs[i][1], p + "[1]", scene_.file));
    }
  }

  std::vector<MeshTriangle> inline_mesh(JsonObject& obj) {
    const Json& ps = obj.get("positions");
    if (!ps.is_array() || ps.size() < 3) obj.fail("positions", "expected an array of at least 3 points");
    std::vector<Vec3> positions, normals;
    std::vector<std::array<float, 2>> uvs;
    for (size_t i = 0; i < ps.size(); ++i)
      positions.push_back(read_vec3(ps[i], obj.child("positions") + "[" + std::to_string(i) + "]", scene_.file));
    if (const Json* ns = obj.find("normals")) {
      if (!ns->is_array() || ns->size() != ps.size()) obj.fail("normals", "expected one normal per position");
      for (size_t i = 0; i < ns->size(); ++i)
        normals.push_back(read_vec3((*ns)[i], obj.child("normals") + "[" + std::to_string(i) + "]", scene_.file));
    }
    if (const Json* us = obj.find("uvs")) {
      if (!us->is_array() || us->size() != ps.size()) obj.fail("uvs", "expected one uv pair per position");
      uvs.resize(us->size());
      read_uvs(*us, obj.child("uvs"), [&](size_t i, float u, float v) { uvs[i] = {u, v}; });
    }
    const Json& is = obj.get("indices");
    if (!is.is_array() || is.empty()) obj.fail("indices", "expected an array of [i, j, k] triangles");
    std::vector<MeshTriangle> tris;
    for (size_t t = 0; t < is.size(); ++t) {
      const std::string p = obj.child("indices") + "[" + std::to_string(t) + "]";
      if (!is[t].is_array() || is[t].size() != 3) fail_at(scene_.file, p, "expected [i, j, k], got " + describe(is[t]));
      MeshTriangle tri;
      for (int c = 0; c < 3; ++c) {
        const Json& iv = is[t][c];
        if (!iv.is_number_unsigned() || iv.get<uint64_t>() >= positions.size())
          fail_at(scene_.file, p + "[" + std::to_string(c) + "]",
                  "expected an index below " + std::to_string(positions.size()) + ", got " + describe(iv));
        const size_t k = iv.get<size_t>();
        tri.p[c] = positions[k];
        if (!normals.empty()) tri.n[c] = normals[k];
        if (!uvs.empty()) tri.uv[c][0] = uvs[k][0], tri.uv[c][1] = uvs[k][1];
      }
      tri.has_normals = !normals.empty();
      tri.has_uvs = !uvs.empty();
      tris.push_back(tri);
    }
    return tris;
  }

  // One material per triangle.
  void add_triangles(JsonObject& obj, std::vector<MeshTriangle> tris, const Transform& xf,
                     const std::vector<uint32_t>& materials) {
    const size_t count = tris.size();
    const size_t kept =
        append_mesh_triangles(scene_, std::move(tris), xf, materials, [&] { obj.fail("normals", "a vertex normal is zero"); });
    if (kept == 0 && count == 1 && obj.string("type") == "triangle")
      obj.fail("vertices", "zero-area triangle (its vertices are collinear or coincide)");
    if (kept == 0) obj.fail(obj.find("file") ? "file" : "indices", "every triangle of the mesh has zero area");
  }

  // A glTF file the shapes place, read once with its materials and textures however many
  // times it is placed; by its canonical path.
  struct PlacedGltf {
    PlacedGltf(GltfFile read, Scene& scene) : file(std::move(read)), materials(file, scene) {}
    GltfFile file;
    GltfMaterials materials;
  };

  Scene& scene_;
  std::string dir_;
  TextureLoader& textures_;
  std::map<std::string, std::unique_ptr<PlacedGltf>> gltf_files_;
};

}  // namespace

void read_shapes(const Json& shapes, const std::string& file, const std::map<std::string, uint32_t>& material_ids,
                 const std::vector<std::string>& material_types, TextureLoader& textures, Scene& scene) {
  if (!shapes.is_array()) fail_at(file, "shapes", "expected an array, got " + describe(shapes));
  ShapeReader reader(scene, std::filesystem::path(file).parent_path().string(), textures);
  for (size_t i = 0; i < shapes.size(); ++i)
    reader.add_shape(shapes[i], "shapes[" + std::to_string(i) + "]", material_ids, material_types);
}

}  // namespace tracer
