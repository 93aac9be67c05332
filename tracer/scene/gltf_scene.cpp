#include "scene/gltf_scene.h"

#include <cmath>
#include <optional>
#include <set>
#include <unordered_set>

#include "io/json_reader.h"
#include "kernel/base/detmath.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_schema.h"
#include "scene/light_reader.h"
#include "scene/mesh_primitives.h"
#include "scene/scene_types.h"

namespace tracer {
namespace {

std::string at(const std::string& array, size_t i) { return array + "[" + std::to_string(i) + "]"; }

constexpr double kUnitQuaternionTolerance = 1e-3;

// A node's local transform: its matrix (column-major, affine), or T R S (glTF 2.0, 3.5.3).
Transform node_transform(const GltfFile& file, const tinygltf::Node& node, const std::string& path) {
  for (const auto* v : {&node.matrix, &node.translation, &node.rotation, &node.scale})
    for (double d : *v) gltf_float(file, d, path);  // every cast below is then in range
  Transform t;
  if (!node.matrix.empty()) {
    const std::vector<double>& m = node.matrix;
    if (m.size() != 16) fail_at(file.path, path + ".matrix", "expected 16 numbers");
    if (m[3] != 0.0 || m[7] != 0.0 || m[11] != 0.0 || m[15] != 1.0)
      fail_at(file.path, path + ".matrix", "is not affine (its last row must be 0, 0, 0, 1)");
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) t.m[c][r] = static_cast<float>(m[c * 4 + r]);
    t.t = {static_cast<float>(m[12]), static_cast<float>(m[13]), static_cast<float>(m[14])};
    t.uniform_scale = false;
    return t;
  }
  if (!node.scale.empty()) {
    if (node.scale.size() != 3) fail_at(file.path, path + ".scale", "expected 3 numbers");
    t = Transform::scaling(
        {static_cast<float>(node.scale[0]), static_cast<float>(node.scale[1]), static_cast<float>(node.scale[2])});
  }
  if (!node.rotation.empty()) {
    if (node.rotation.size() != 4) fail_at(file.path, path + ".rotation", "expected a quaternion of 4 numbers");
    // A rotation is a unit quaternion (glTF 2.0, 5.25): [0, 0, 0, 0] or [2, 0, 0, 0] would shear or
    // scale. Exporters round, so a length within 1e-3 of 1 is taken as written.
    double length2 = 0.0;
    for (const double q : node.rotation) length2 += q * q;
    if (!(std::fabs(std::sqrt(length2) - 1.0) <= kUnitQuaternionTolerance))
      fail_at(file.path, path + ".rotation",
              "is not a unit quaternion (its length is " + std::to_string(std::sqrt(length2)) + ")");
    const float x = static_cast<float>(node.rotation[0]), y = static_cast<float>(node.rotation[1]);
    const float z = static_cast<float>(node.rotation[2]), w = static_cast<float>(node.rotation[3]);
    Transform r;  // the unit quaternion's rotation matrix, column by column
    r.m[0] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w)};
    r.m[1] = {2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)};
    r.m[2] = {2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)};
    t = t.then(r);
  }
  if (!node.translation.empty()) {
    if (node.translation.size() != 3) fail_at(file.path, path + ".translation", "expected 3 numbers");
    t = t.then(Transform::translation({static_cast<float>(node.translation[0]), static_cast<float>(node.translation[1]),
                                       static_cast<float>(node.translation[2])}));
  }
  return t;
}

class GltfSceneReader {
 public:
  GltfSceneReader(const GltfFile& file, bool with_lights, Scene& scene, GltfMaterials& materials)
      : file_(file), model_(file.model), with_lights_(with_lights), scene_(scene), materials_(materials) {}

  GltfContents read(const Transform& placement) {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      const size_t s = model_.defaultScene >= 0 ? static_cast<size_t>(model_.defaultScene) : 0;
      if (s >= model_.scenes.size()) fail_at(file_.path, "scene", "names a scene the file does not have");
      roots = model_.scenes[s].nodes;
    } else {  // no scenes: every node no other node names as a child
      std::set<int> children;
      for (const tinygltf::Node& n : model_.nodes) children.insert(n.children.begin(), n.children.end());
      for (size_t i = 0; i < model_.nodes.size(); ++i)
        if (!children.count(static_cast<int>(i))) roots.push_back(static_cast<int>(i));
    }
    // Depth first with an explicit stack: a hostile hierarchy cannot exhaust the call stack.
    std::vector<std::pair<int, Transform>> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, placement);
    std::set<int> seen;
    while (!stack.empty()) {
      const auto [index, parent] = stack.back();
      stack.pop_back();
      const std::string path = at("nodes", static_cast<size_t>(std::max(index, 0)));
      if (index < 0 || static_cast<size_t>(index) >= model_.nodes.size())
        fail_at(file_.path, "nodes",
                "node " + std::to_string(index) + " is named, but the file has " + std::to_string(model_.nodes.size()));
      if (!seen.insert(index).second)
        fail_at(file_.path, path, "is reached twice (a cycle, or a node with two parents: glTF's nodes form trees)");
      const tinygltf::Node& node = model_.nodes[index];
      const Transform world = node_transform(file_, node, path).then(parent);
      if (node.mesh >= 0) add_mesh(node.mesh, world, path);
      if (node.camera >= 0) add_camera(node, world, path);
      if (node.skin >= 0) ignore(path + ".skin (drawn in the bind pose)");
      if (const auto light = node.extensions.find("KHR_lights_punctual"); light != node.extensions.end())
        add_light(light->second, world, path);
      for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) stack.emplace_back(*c, world);
    }
    contents_.materials = static_cast<uint32_t>(materials_used_.size());
    contents_.textures = static_cast<uint32_t>(materials_.texture_count());
    for (const std::string& s : materials_.ignored()) contents_.ignored.push_back(s);
    for (const std::string& s : file_.notes) contents_.ignored.push_back("tinygltf: " + s);
    for (size_t i = 0; i < model_.extensionsUsed.size(); ++i)
      if (!gltf_extension_read(model_.extensionsUsed[i]))
        contents_.ignored.push_back(at("extensionsUsed", i) + ": " + model_.extensionsUsed[i] + " (not read)");
    return contents_;
  }

 private:
  // Each part left out once, in the order met (a set beside the list: 160,000 distinct parts
  // took 52 s by a linear search).
  void ignore(const std::string& what) {
    if (ignored_seen_.insert(what).second) contents_.ignored.push_back(what);
  }

  void add_mesh(int index, const Transform& world, const std::string& node_path) {
    if (static_cast<size_t>(index) >= model_.meshes.size())
      fail_at(file_.path, node_path + ".mesh",
              "names mesh " + std::to_string(index) + "; the file has " + std::to_string(model_.meshes.size()));
    const tinygltf::Mesh& mesh = model_.meshes[index];
    ++contents_.meshes;
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const std::string path = at("meshes", index) + "." + at("primitives", p);
      const tinygltf::Primitive& prim = mesh.primitives[p];
      if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
          prim.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        ignore(path + ": mode " + std::to_string(prim.mode) + " (points and lines are left out)");
        continue;
      }
      if (attribute(prim, "POSITION") < 0) {  // glTF 2.0, 3.7.2.1: a client skips it
        ignore(path + ": no POSITION (not drawn)");
        continue;
      }
      if (!prim.targets.empty()) ignore(path + ".targets (drawn without morph targets)");
      GltfUvTransform uv;
      const uint32_t material = materials_.material(prim.material, uv);
      materials_used_.insert(material);
      std::vector<MeshTriangle> tris = triangles(prim, path, uv);
      contents_.triangles += static_cast<uint32_t>(tris.size());
      const std::vector<uint32_t> ids(tris.size(), material);
      append_mesh_triangles(scene_, std::move(tris), world, ids,
                            [&] { fail_at(file_.path, path + ".attributes.NORMAL", "a vertex normal is zero"); });
    }
  }

  int attribute(const tinygltf::Primitive& prim, const char* name) const {
    const auto it = prim.attributes.find(name);
    return it == prim.attributes.end() ? -1 : it->second;
  }

  std::vector<MeshTriangle> triangles(const tinygltf::Primitive& prim, const std::string& path,
                                      const GltfUvTransform& uv_transform) {
    const std::string attrs = path + ".attributes";
    const int position = attribute(prim, "POSITION");
    const std::vector<float> p = read_gltf_floats(model_, position, 3, file_.path, attrs + ".POSITION");
    const size_t vertices = p.size() / 3;
    const auto same_count = [&](const std::vector<float>& v, size_t per, const char* name) {
      if (!v.empty() && v.size() / per != vertices)
        fail_at(file_.path, attrs + "." + name,
                "has " + std::to_string(v.size() / per) + " elements; POSITION has " + std::to_string(vertices));
    };
    std::vector<float> n, uv, tangent;
    if (attribute(prim, "NORMAL") >= 0)
      n = read_gltf_floats(model_, attribute(prim, "NORMAL"), 3, file_.path, attrs + ".NORMAL");
    if (attribute(prim, "TEXCOORD_0") >= 0)
      uv = read_gltf_floats(model_, attribute(prim, "TEXCOORD_0"), 2, file_.path, attrs + ".TEXCOORD_0");
    if (attribute(prim, "TANGENT") >= 0 && !uv.empty())
      tangent = read_gltf_floats(model_, attribute(prim, "TANGENT"), 4, file_.path, attrs + ".TANGENT");
    same_count(n, 3, "NORMAL");
    same_count(uv, 2, "TEXCOORD_0");
    same_count(tangent, 4, "TANGENT");
    std::vector<uint32_t> index;
    if (prim.indices >= 0) {
      index = read_gltf_indices(model_, prim.indices, file_.path, path + ".indices");
    } else {
      index.resize(vertices);
      for (size_t i = 0; i < vertices; ++i) index[i] = static_cast<uint32_t>(i);
    }
    const std::vector<uint32_t> corners = triangle_corners(prim.mode, index, path);
    // Every triangle placed counts, those of zero area too (built, tested and left out: 2.1e9 of
    // them took 12 minutes when only the kept ones counted).
    placed_triangles_ += corners.size() / 3;
    if (placed_triangles_ > kMaxGltfTriangles || scene_.primitives.size() + corners.size() / 3 > kMaxGltfTriangles)
      fail_at(file_.path, path, "would place more than 2^24 triangles, the limit of a glTF file (instances count)");
    std::vector<MeshTriangle> tris(corners.size() / 3);
    for (size_t t = 0; t < tris.size(); ++t) {
      MeshTriangle& tri = tris[t];
      for (int c = 0; c < 3; ++c) {
        const uint32_t k = corners[t * 3 + c];
        if (k >= vertices)
          fail_at(
              file_.path, path + ".indices",
              "index " + std::to_string(k) + " is beyond the " + std::to_string(vertices) + " vertices of POSITION");
        tri.p[c] = {p[k * 3], p[k * 3 + 1], p[k * 3 + 2]};
        if (!n.empty()) tri.n[c] = {n[k * 3], n[k * 3 + 1], n[k * 3 + 2]};
        if (!uv.empty()) {
          float st[2] = {uv[k * 2], uv[k * 2 + 1]};
          uv_transform.apply(st);
          if (!is_finite(st[0]) || !is_finite(st[1]))  // offset and scale each finite, their sum not
            fail_at(file_.path, attrs + ".TEXCOORD_0",
                    "vertex " + std::to_string(k) +
                        "'s coordinates leave float's range under the material's "
                        "KHR_texture_transform");
          tri.uv[c][0] = st[0];
          tri.uv[c][1] = 1.0f - st[1];  // glTF's v runs down the image, the tracer's up
        }
        if (!tangent.empty()) tri.tangent[c] = {tangent[k * 4], tangent[k * 4 + 1], tangent[k * 4 + 2]};
      }
      // w = -1 marks mirrored uvs: the bitangent is w (n x t) (glTF 2.0, 3.7.2.1); the first
      // corner's sign holds for the triangle.
      if (!tangent.empty() && tangent[corners[t * 3] * 4 + 3] < 0.0f) tri.bitangent_sign = -1.0f;
      tri.has_normals = !n.empty();
      tri.has_uvs = !uv.empty();
      tri.has_tangents = !tangent.empty();
    }
    return tris;
  }

  // Three vertex indices per triangle of a list, strip or fan (glTF 2.0, 3.7.2.1).
  std::vector<uint32_t> triangle_corners(int mode, const std::vector<uint32_t>& index, const std::string& path) {
    if (mode == TINYGLTF_MODE_TRIANGLES) {
      if (index.size() % 3 != 0) ignore(path + ": an index count that is not a multiple of 3 (the rest is left out)");
      return std::vector<uint32_t>(index.begin(), index.end() - static_cast<std::ptrdiff_t>(index.size() % 3));
    }
    std::vector<uint32_t> out;
    for (size_t i = 0; i + 2 < index.size(); ++i) {
      if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
        out.insert(out.end(), {index[i], index[i + 1 + i % 2], index[i + 2 - i % 2]});
      else
        out.insert(out.end(), {index[i + 1], index[i + 2], index[0]});
    }
    return out;
  }

  void add_camera(const tinygltf::Node& node, const Transform& world, const std::string& path) {
    const size_t index = static_cast<size_t>(node.camera);
    if (index >= model_.cameras.size())
      fail_at(file_.path, path + ".camera",
              "names camera " + std::to_string(index) + "; the file has " + std::to_string(model_.cameras.size()));
    const tinygltf::Camera& cam = model_.cameras[index];
    const std::string cam_path = at("cameras", index);
    if (cam.type != "perspective") {
      ignore(cam_path + ": " + cam.type + " (only perspective cameras are read)");
      return;
    }
    const double yfov = cam.perspective.yfov, aspect = cam.perspective.aspectRatio;
    if (!(yfov > 0.0 && yfov < 3.14159)) fail_at(file_.path, cam_path + ".perspective.yfov", "must be in (0, pi)");
    if (!(aspect >= 0.0 && aspect < 1e4) || (aspect > 0.0 && aspect < 1e-4))
      fail_at(file_.path, cam_path + ".perspective.aspectRatio", "must be above 0 and below 1e4");
    GltfCamera c;
    c.index = static_cast<int>(index);
    c.name = !cam.name.empty() ? cam.name : node.name;
    c.spec.from = world.point({0, 0, 0});
    const Vec3 ahead = world.vector({0, 0, -1}), up = world.vector({0, 1, 0});  // glTF cameras look down -z
    if (!(length(ahead) > 0.0f) || !(length(cross(up, ahead)) > 0.0f) || !is_finite(c.spec.from))
      fail_at(file_.path, path, "its transform leaves the camera without a view direction");
    c.spec.to = c.spec.from + normalize(ahead);
    c.spec.up = up;
    c.spec.vfov_degrees = static_cast<float>(yfov * (180.0 / 3.14159265358979323846));
    c.spec.aperture = 0.0f;
    c.spec.focus_distance = 1.0f;
    c.aspect = static_cast<float>(aspect);
    contents_.cameras.push_back(c);
  }

  void add_light(const tinygltf::Value& ext, const Transform& world, const std::string& node_path) {
    if (!ext.IsObject() || !ext.Has("light") || !ext.Get("light").IsInt())
      fail_at(file_.path, node_path + ".extensions.KHR_lights_punctual", "expected {\"light\": INDEX}");
    const int index = ext.Get("light").GetNumberAsInt();
    if (index < 0 || static_cast<size_t>(index) >= model_.lights.size())
      fail_at(file_.path, node_path + ".extensions.KHR_lights_punctual.light",
              "names light " + std::to_string(index) + "; the file has " + std::to_string(model_.lights.size()));
    if (!with_lights_) return;
    const tinygltf::Light& l = model_.lights[index];
    const std::string path = "extensions.KHR_lights_punctual." + at("lights", index);
    const std::optional<LightKind> kind = declared_light_kind(l.type);
    if (!kind)
      fail_at(file_.path, path + ".type",
              "a light of type \"" + l.type + "\"" + (l.name.empty() ? "" : " (\"" + l.name + "\")") +
                  ": expected point, spot or directional");
    Vec3 colour{1, 1, 1};
    if (!l.color.empty()) {
      if (l.color.size() != 3) fail_at(file_.path, path + ".color", "expected 3 numbers");
      colour = {gltf_float(file_, l.color[0], path + ".color[0]"), gltf_float(file_, l.color[1], path + ".color[1]"),
                gltf_float(file_, l.color[2], path + ".color[2]")};
    }
    const float intensity = gltf_float(file_, l.intensity, path + ".intensity");
    if (!(intensity >= 0.0f && intensity < 1e30f) || !(colour.x >= 0 && colour.y >= 0 && colour.z >= 0) ||
        !is_finite(colour))
      fail_at(file_.path, path, "color and intensity must be finite and >= 0");
    if (l.range > 0.0 && l.type != "directional") ignore(path + ".range (light falls off as 1/d^2 everywhere)");
    Light p{};
    p.kind = *kind;
    // candela (point, spot) and lux (directional): the tracer's radiance unit is the nit (docs/gltf.md)
    p.intensity = colour * intensity;
    if (!(max_component(p.intensity) < 1e30f))  // each below, their product past float's range
      fail_at(file_.path, path, "color x intensity must be below 1e30");
    if (p.kind != LightKind::Directional) p.position = world.point({0, 0, 0});
    if (p.kind != LightKind::Point) {  // a spot and a sun shine along the node's -z
      if (const std::string why = set_light_direction(p, world.vector({0, 0, -1})); !why.empty())
        fail_at(file_.path, node_path, "the node's transform gives its " + l.type + " light no direction: " + why);
    }
    if (p.kind == LightKind::Spot) {
      const double inner = gltf_float(file_, l.spot.innerConeAngle, path + ".spot.innerConeAngle"),
                   outer = gltf_float(file_, l.spot.outerConeAngle, path + ".spot.outerConeAngle");
      if (const std::string why = set_spot_cone(p, inner, outer); !why.empty())
        fail_at(file_.path, path + ".spot", why + " (in radians: 0 <= innerConeAngle <= outerConeAngle <= pi/2)");
    }
    scene_.lights.push_back(p);
    scene_.report.used_types.insert("light:" + l.type);
    ++contents_.lights;
  }

  const GltfFile& file_;
  const tinygltf::Model& model_;
  bool with_lights_;
  Scene& scene_;
  GltfMaterials& materials_;
  std::set<uint32_t> materials_used_;
  GltfContents contents_;
  std::unordered_set<std::string> ignored_seen_;
  uint64_t placed_triangles_ = 0;
};

}  // namespace

GltfContents add_gltf_file(const GltfFile& file, const Transform& placement, bool with_lights, Scene& scene,
                           GltfMaterials& materials) {
  scene.report.input_files.insert(file.files_read.begin(), file.files_read.end());
  return GltfSceneReader(file, with_lights, scene, materials).read(placement);
}

GltfContents add_gltf_file(const GltfFile& file, const Transform& placement, bool with_lights, Scene& scene) {
  GltfMaterials materials(file, scene);
  return add_gltf_file(file, placement, with_lights, scene, materials);
}

}  // namespace tracer
