#include "scene/scene_loader.h"

#include <chrono>
#include <filesystem>

#include "accel/acceleration.h"
#include "accel/bounds.h"
#include "scene/camera_setup.h"
#include "scene/json_reader.h"
#include "scene/light_table.h"
#include "kernel/integrator/ray_counts.h"
#include "scene/mesh.h"
#include "scene/mesh_tangents.h"
#include "scene/mtl_materials.h"
#include "scene/scene_types.h"
#include "io/text_file.h"
#include "scene/texture_loader.h"
#include "scene/transform.h"

namespace tracer {
namespace {

constexpr uint32_t kMaxResolution = 16384;

// Whether normalize(cross(e1, e2)), as surface.h computes a triangle's or quad's normal,
// is a finite unit vector: false for zero area (collinear or coincident corners) and for
// cross products whose squared length under- or overflows a float.
bool has_unit_normal(Vec3 e1, Vec3 e2) {
  const Vec3 n = normalize(cross(e1, e2));
  return is_finite(n) && length(n) > 0.5f;
}

// Reads the `type` key of a section and checks it against the loader's table.
std::string read_type(JsonObject& obj, const std::string& category) {
  const std::string type = obj.string("type");
  if (!is_accepted_type(category, type))
    obj.fail("type", "unknown " + category + " type \"" + type + "\" (expected " + expected_types(category) + ")");
  return type;
}

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
    const std::string fresnel = obj.string_or("fresnel", "schlick");
    if (fresnel == "exact") m.fresnel = FresnelKind::Exact;
    else if (fresnel != "schlick") obj.fail("fresnel", "expected \"schlick\" or \"exact\", got \"" + fresnel + "\"");
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
    m.albedo = textures.colour_or(obj, "albedo", {0.0f, 0.0f, 0.0f}, m.texture[kSlotAlbedo]);  // an emitter that also reflects
  }
  if (type != "dielectric" && type != "emissive") {  // surfaces with a diffuse or glossy response
    m.normal_map = textures.data_map(obj, "normal_map");
    m.bump_map = textures.data_map(obj, "bump_map");
    if (m.normal_map != kNoTexture && m.bump_map != kNoTexture) obj.fail("bump_map", "give a normal_map or a bump_map, not both");
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
      const Vec3 f = s->is_number() ? Vec3{1, 1, 1} * read_number(*s, step.child("scale"), file)
                                    : step.vec3("scale");
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

class SceneBuilder {
 public:
  SceneBuilder(Scene& scene, const std::string& dir, TextureLoader& textures)
      : scene_(scene), dir_(dir), textures_(textures) {}

  void add_shape(const Json& value, const std::string& path,
                 const std::map<std::string, uint32_t>& material_ids,
                 const std::vector<std::string>& material_types) {
    JsonObject obj(value, path, scene_.file);
    const std::string type = obj.string("type");
    if (!is_accepted_type("shape", type))
      obj.fail("type", "unknown shape type \"" + type + "\" (expected " + expected_types("shape") + ")");
    const Json* tv = obj.find("transform");
    const Transform xf = tv ? read_transform(*tv, obj.child("transform"), scene_.file, scene_.used_types) : Transform{};
    const Json* mat = obj.find("material");
    if (!mat && type == "mesh" && obj.find("file")) return add_mtl_mesh(obj, xf);
    if (!mat) obj.fail("material", type == "mesh" ? "missing: give the mesh a \"material\", or a file whose MTL has them"
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
        const auto tris = load_obj((std::filesystem::path(dir_) / rel).string(), scene_.file, obj.child("file"));
        add_triangles(obj, tris, xf, std::vector<uint32_t>(tris.size(), material));
      } else {
        const auto tris = inline_mesh(obj);
        add_triangles(obj, tris, xf, std::vector<uint32_t>(tris.size(), material));
      }
    }
    obj.finish();
    ++scene_.shape_counts[type];
    scene_.used_types.insert("shape:" + type);
    scene_.used_types.insert("material:" + material_types[material]);
  }

 private:
  // A mesh whose faces take the materials of its OBJ's MTL file (mtl_materials.h); faces
  // with no usemtl get a grey lambert.
  void add_mtl_mesh(JsonObject& obj, const Transform& xf) {
    const std::filesystem::path file = std::filesystem::path(dir_) / obj.string("file");
    for (const char* k : {"positions", "indices", "normals", "uvs"})
      if (obj.find(k)) obj.fail(k, "a mesh has either \"file\" or inline data, not both");
    std::vector<MtlMaterial> mtls;
    const auto tris = load_obj(file.string(), scene_.file, obj.child("file"), &mtls);
    const uint32_t base = static_cast<uint32_t>(scene_.materials.size());
    for (const MtlMaterial& mtl : mtls) {
      std::string type;
      scene_.materials.push_back(material_from_mtl(mtl, textures_, file.parent_path().string(), obj.child("file"), type));
      scene_.material_names.push_back(file.filename().string() + ":" + mtl.name);
      scene_.used_types.insert("material:" + type);
    }
    Material grey{};
    grey.kind = MaterialKind::Lambert;
    grey.albedo = {0.5f, 0.5f, 0.5f};
    for (uint32_t& t : grey.texture) t = kNoTexture;
    grey.specular_map = grey.normal_map = grey.bump_map = kNoTexture;
    const uint32_t fallback = static_cast<uint32_t>(scene_.materials.size());
    scene_.materials.push_back(grey);
    scene_.material_names.push_back(file.filename().string() + ":(no usemtl)");
    std::vector<uint32_t> materials;
    for (const MeshTriangle& t : tris) materials.push_back(t.mtl >= 0 ? base + static_cast<uint32_t>(t.mtl) : fallback);
    add_triangles(obj, tris, xf, materials);
    obj.finish();
    ++scene_.shape_counts["mesh"];
    scene_.used_types.insert("shape:mesh");
  }

  void add(const Primitive& p) {
    if (!is_finite(p.a) || !is_finite(p.b) || !is_finite(p.c) || !is_finite(p.radius))
      throw InputError(scene_.file + ": a transformed shape has non-finite coordinates");
    scene_.primitives.push_back(p);
  }

  void add_quad(JsonObject& obj, Vec3 corner, Vec3 u, Vec3 v, uint32_t material) {
    if (!has_unit_normal(u, v)) obj.fail("", "zero-area quad (u and v are parallel or zero, or its normal under- or overflows a float)");
    add({ShapeKind::Quad, material, -1, 0.0f, corner, u, v});
  }

  void add_box(JsonObject& obj, Vec3 lo, Vec3 hi, const Transform& xf, uint32_t material) {
    const Vec3 dx = {hi.x - lo.x, 0, 0}, dy = {0, hi.y - lo.y, 0}, dz = {0, 0, hi.z - lo.z};
    // Six faces with outward normals cross(u, v).
    const Vec3 faces[6][3] = {{lo, dx, dz},      {lo, dy, dx},      {lo, dz, dy},
                              {hi, -dz, -dx},    {hi, -dx, -dy},    {hi, -dy, -dz}};
    for (const auto& f : faces) add_quad(obj, xf.point(f[0]), xf.vector(f[1]), xf.vector(f[2]), material);
  }

  MeshTriangle inline_triangle(JsonObject& obj) {
    const Json& vs = obj.get("vertices");
    if (!vs.is_array() || vs.size() != 3) obj.fail("vertices", "expected 3 vertices, got " + describe(vs));
    MeshTriangle t;
    for (int i = 0; i < 3; ++i) t.p[i] = read_vec3(vs[i], obj.child("vertices") + "[" + std::to_string(i) + "]", scene_.file);
    if (const Json* ns = obj.find("normals")) {
      if (!ns->is_array() || ns->size() != 3) obj.fail("normals", "expected 3 normals, got " + describe(*ns));
      for (int i = 0; i < 3; ++i) t.n[i] = read_vec3((*ns)[i], obj.child("normals") + "[" + std::to_string(i) + "]", scene_.file);
      t.has_normals = true;
    }
    if (const Json* uvs = obj.find("uvs")) {
      if (!uvs->is_array() || uvs->size() != 3) obj.fail("uvs", "expected 3 uv pairs, got " + describe(*uvs));
      read_uvs(*uvs, obj.child("uvs"), [&](size_t i, float u, float v) { t.uv[i][0] = u; t.uv[i][1] = v; });
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
          fail_at(scene_.file, p + "[" + std::to_string(c) + "]", "expected an index below " + std::to_string(positions.size()) + ", got " + describe(iv));
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
    compute_vertex_tangents(tris);
    const bool single = obj.string("type") == "triangle";
    size_t kept = 0;
    for (size_t i = 0; i < tris.size(); ++i) {
      const MeshTriangle& t = tris[i];
      const Vec3 a = xf.point(t.p[0]), b = xf.point(t.p[1]), c = xf.point(t.p[2]);
      // A triangle without a geometric normal (surface.h) can never be shaded: left out.
      if (!has_unit_normal(b - a, c - a)) continue;
      ++kept;
      const uint32_t material = materials[i];
      int32_t shading = -1;
      if (t.has_normals || t.has_uvs) {
        TriangleShading sh{};
        if (t.has_normals) {
          for (int c = 0; c < 3; ++c)
            if (!(length(t.n[c]) > 0.0f)) obj.fail("normals", "a vertex normal is zero");
          sh.n0 = xf.normal(t.n[0]);
          sh.n1 = xf.normal(t.n[1]);
          sh.n2 = xf.normal(t.n[2]);
          sh.has_normals = 1;
        }
        if (t.has_uvs) {
          sh.u0 = t.uv[0][0], sh.v0 = t.uv[0][1], sh.u1 = t.uv[1][0], sh.v1 = t.uv[1][1];
          sh.u2 = t.uv[2][0], sh.v2 = t.uv[2][1];
          sh.has_uvs = 1;
        }
        if (t.has_tangents) {
          sh.t0 = xf.vector(t.tangent[0]);
          sh.t1 = xf.vector(t.tangent[1]);
          sh.t2 = xf.vector(t.tangent[2]);
          sh.has_tangents = 1;
        }
        shading = static_cast<int32_t>(scene_.triangle_shading.size());
        scene_.triangle_shading.push_back(sh);
      }
      add({ShapeKind::Triangle, material, shading, 0.0f, a, b, c});
    }
    if (kept == 0 && single) obj.fail("vertices", "zero-area triangle (its vertices are collinear or coincide)");
    if (kept == 0) obj.fail(obj.find("file") ? "file" : "indices", "every triangle of the mesh has zero area");
    scene_.degenerate_triangles += static_cast<uint32_t>(tris.size() - kept);
  }

  Scene& scene_;
  std::string dir_;
  TextureLoader& textures_;
};

// The enum value of a name is its index in the loader's table (scene_types.cpp), which
// lists the names in the enum's order.
template <class Kind>
Kind parse_kind(const std::string& category, const std::string& name, const std::string& where) {
  const auto& names = accepted_scene_types().at(category);
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<Kind>(i);
  throw InputError(where + ": unknown " + category + " \"" + name + "\" (expected " + expected_types(category) + ")");
}

SamplerKind parse_sampler(const std::string& name, const std::string& where) {
  return parse_kind<SamplerKind>("sampler", name, where);
}

IntegratorKind parse_integrator(const std::string& name, const std::string& where) {
  return parse_kind<IntegratorKind>("integrator", name, where);
}

AccelKind parse_accel(const std::string& name, const std::string& where) {
  return parse_kind<AccelKind>("accel", name, where);
}

uint32_t read_count(JsonObject& obj, const std::string& key, uint64_t fallback) {
  return obj.find(key) ? static_cast<uint32_t>(std::min<uint64_t>(obj.unsigned_integer(key), 0xffffffffu)) : static_cast<uint32_t>(fallback);
}

void read_render(const Json* value, const std::string& file, const RenderOverrides& ov, Scene& scene,
                 JsonObject& film) {
  RenderSettings& rs = scene.settings;
  const Json empty = Json::object();
  JsonObject obj(value ? *value : empty, "render", file);
  const std::string cli = file + ": command line";
  rs.spp = read_count(obj, "spp", 1);
  std::string sampler = obj.string_or("sampler", "stochastic");
  std::string integrator = obj.string_or("integrator", "whitted");
  std::string accel = obj.string_or("accel", "bvh");
  rs.max_depth = read_count(obj, "max_depth", 5);
  rs.seed = obj.find("seed") ? obj.unsigned_integer("seed") : 0;
  rs.nee = obj.boolean_or("nee", true) ? 1u : 0u;
  rs.sky_sampling = obj.boolean_or("sky_sampling", true) ? 1u : 0u;
  std::string triangle_test = obj.string_or("triangle_test", "watertight");
  rs.rr_depth = read_count(obj, "rr_depth", 3);
  rs.grid_resolution = read_count(obj, "grid_resolution", 0);
  obj.finish();
  rs.width = read_count(film, "width", 0);
  rs.height = read_count(film, "height", 0);
  film.finish();
  // Command-line overrides; their errors name the option.
  const bool cli_spp = ov.spp.has_value(), cli_sampler = ov.sampler.has_value();
  if (ov.spp) rs.spp = *ov.spp;
  if (ov.width) rs.width = *ov.width;
  if (ov.height) rs.height = *ov.height;
  if (ov.max_depth) rs.max_depth = *ov.max_depth;
  if (ov.seed) rs.seed = *ov.seed;
  rs.effects = ov.effects.value_or(kEffectAll);
  if (ov.nee) rs.nee = *ov.nee ? 1u : 0u;
  if (ov.sky_sampling) rs.sky_sampling = *ov.sky_sampling ? 1u : 0u;
  if (ov.rr_depth) rs.rr_depth = *ov.rr_depth;
  if (ov.grid_resolution) rs.grid_resolution = *ov.grid_resolution;
  if (rs.grid_resolution > 1024)
    throw InputError((ov.grid_resolution ? cli + " --grid-resolution" : file + ": render.grid_resolution") +
                     ": must be at most 1024 cells along the longest axis");
  if (ov.triangle_test) triangle_test = *ov.triangle_test;
  if (triangle_test != "watertight" && triangle_test != "moller-trumbore")
    throw InputError((ov.triangle_test ? cli + " --triangle-test" : file + ": render.triangle_test") + ": unknown test \"" +
                     triangle_test + "\" (expected watertight or moller-trumbore)");
  rs.triangle_test = triangle_test == "watertight" ? TriangleTest::Watertight : TriangleTest::MollerTrumbore;
  if (ov.sampler) sampler = *ov.sampler;
  if (ov.integrator) integrator = *ov.integrator;
  if (ov.accel) accel = *ov.accel;
  const std::string spp_at = cli_spp ? cli + " --spp" : file + ": render.spp";
  const std::string sampler_at = cli_sampler ? cli + " --sampler" : file + ": render.sampler";
  rs.sampler = parse_sampler(sampler, sampler_at);
  rs.integrator = parse_integrator(integrator, ov.integrator ? cli + " --integrator" : file + ": render.integrator");
  rs.accel = parse_accel(accel, ov.accel ? cli + " --accel" : file + ": render.accel");
  scene.used_types.insert("sampler:" + sampler);
  scene.used_types.insert("integrator:" + integrator);
  scene.used_types.insert("accel:" + accel);
  if (rs.spp == 0) throw InputError(spp_at + ": spp must be at least 1");
  if (rs.max_depth > kMaxDepth)
    throw InputError((ov.max_depth ? cli + " --max-depth" : file + ": render.max_depth") + ": must be at most " + std::to_string(kMaxDepth));
  for (const auto& [size, name, set] : {std::tuple{rs.width, "width", ov.width.has_value()}, std::tuple{rs.height, "height", ov.height.has_value()}})
    if (size < 1 || size > kMaxResolution)
      throw InputError((set ? cli + " --" + name : file + ": film." + name) + ": must be in [1, " + std::to_string(kMaxResolution) + "], got " + std::to_string(size));
  rs.grid_n = 1;
  while (rs.grid_n * rs.grid_n < rs.spp) ++rs.grid_n;
  if (rs.sampler == SamplerKind::Center && rs.spp != 1)
    throw InputError(sampler_at + ": the center sampler takes exactly 1 spp, got " + std::to_string(rs.spp));
  if ((rs.sampler == SamplerKind::Grid || rs.sampler == SamplerKind::Stratified) && rs.grid_n * rs.grid_n != rs.spp)
    throw InputError(spp_at + ": the " + sampler + " sampler needs a square spp (1, 4, 9, 16, ...), got " + std::to_string(rs.spp));
}

void read_camera(const Json& value, const std::string& file, Scene& scene) {
  JsonObject obj(value, "camera", file);
  CameraSpec spec;
  spec.from = obj.vec3("from");
  spec.to = obj.vec3("to");
  spec.up = obj.vec3_or("up", {0, 1, 0});
  spec.vfov_degrees = obj.number("vfov");
  spec.aperture = obj.number_or("aperture", 0.0f);
  const float dist = length(spec.to - spec.from);
  spec.focus_distance = obj.number_or("focus_distance", dist);
  if (!(dist > 0.0f)) obj.fail("to", "must differ from camera.from");
  if (!(spec.vfov_degrees > 0.0f && spec.vfov_degrees < 180.0f)) obj.fail("vfov", "must be in (0, 180) degrees");
  if (!(spec.aperture >= 0.0f)) obj.fail("aperture", "must be >= 0");
  if (!(spec.focus_distance > 0.0f)) obj.fail("focus_distance", "must be > 0");
  if (!(length(cross(spec.up, spec.to - spec.from)) > 0.0f)) obj.fail("up", "must not be parallel to the view direction");
  obj.finish();
  scene.camera = make_camera(spec, scene.settings.width, scene.settings.height);
  if (spec.aperture > 0.0f) scene.features |= kFeatureThinLens;
}

Background read_background(const Json* value, const std::string& file, std::string& type, TextureLoader& textures) {
  Background bg{BackgroundKind::Constant, {0, 0, 0}, {0, 0, 0}, {kNoTexture, kNoTexture, kNoTexture, kNoTexture, kNoTexture, kNoTexture}};
  type = "constant";
  if (!value) return bg;
  JsonObject obj(*value, "background", file);
  type = obj.string("type");
  read_type(obj, "background");
  if (type == "constant") {
    bg.radiance = obj.color("radiance");
  } else if (type == "gradient") {
    bg.kind = BackgroundKind::Gradient;
    bg.radiance = obj.color("zenith");
    bg.horizon = obj.color("horizon");
  } else if (type == "cubemap") {
    bg.kind = BackgroundKind::Cubemap;
    textures.cube_faces(obj, bg.faces);
  }
  obj.finish();
  return bg;
}

PointLight read_light(const Json& value, const std::string& path, const std::string& file,
                      std::set<std::string>& used_types) {
  JsonObject obj(value, path, file);
  const std::string type = obj.string("type");
  if (!is_accepted_type("light", type))
    obj.fail("type", "unknown light type \"" + type + "\" (expected " + expected_types("light") +
                         "; emissive shapes are area lights)");
  used_types.insert("light:" + type);
  PointLight l{};
  l.position = obj.vec3("position");
  l.intensity = obj.color("intensity");
  if (obj.find("attenuation")) {
    const Vec3 k = obj.vec3("attenuation");
    if (k.x < 0 || k.y < 0 || k.z < 0 || (k.x == 0 && k.y == 0 && k.z == 0))
      obj.fail("attenuation", "expected [kc, kl, kq] >= 0, not all zero");
    l.kc = k.x, l.kl = k.y, l.kq = k.z;
    l.has_attenuation = 1;
  }
  obj.finish();
  return l;
}

uint32_t shape_feature(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::Sphere: return kFeatureSphere;
    case ShapeKind::Plane: return kFeaturePlane;
    case ShapeKind::Triangle: return kFeatureTriangle;
    case ShapeKind::Quad: return kFeatureQuad;
  }
  return 0;
}

// kernel/geom/ray_offset.h's scale: the smallest power of two at least the scene's size (its
// geometry, camera and lights), at most 1.
float ray_offset_scale(const Scene& scene) {
  Bounds b;
  for (const Primitive& p : scene.primitives) {
    if (p.kind == ShapeKind::Plane) b.grow(p.a);
    else b.grow(primitive_bounds(p));
  }
  b.grow(scene.camera.origin);
  for (const PointLight& l : scene.lights) b.grow(l.position);
  const Vec3 d = b.hi - b.lo;
  const float size = std::max(d.x, std::max(d.y, d.z));
  float scale = 1.0f;
  while (scale * 0.5f >= size && scale > 0x1p-100f) scale *= 0.5f;
  return scale;
}

}  // namespace

Scene load_scene_text(const std::string& text, const std::string& path, const RenderOverrides& overrides) {
  Scene scene;
  scene.file = path;
  const Json root = parse_json_text(text, path);
  JsonObject top(root, "", path);
  const std::string format = top.string("format");
  if (format != "tracer-scene/1") top.fail("format", "expected \"tracer-scene/1\", got \"" + format + "\"");

  JsonObject film(top.get("film"), "film", path);
  read_render(top.find("render"), path, overrides, scene, film);
  read_camera(top.get("camera"), path, scene);
  TextureLoader textures(scene, std::filesystem::path(path).parent_path().string());
  std::string background_type;
  scene.background = read_background(top.find("background"), path, background_type, textures);
  scene.used_types.insert("background:" + background_type);
  scene.ambient = top.find("ambient") ? top.color("ambient") : Vec3{0, 0, 0};

  std::map<std::string, uint32_t> material_ids;
  std::vector<std::string> material_types;
  JsonObject materials(top.get("materials"), "materials", path);
  for (const auto& item : top.get("materials").items()) {
    materials.find(item.key());
    material_ids[item.key()] = static_cast<uint32_t>(scene.materials.size());
    material_types.emplace_back();
    scene.materials.push_back(read_material(item.value(), materials.child(item.key()), path, material_types.back(), textures));
    scene.material_names.push_back(item.key());
  }

  if (const Json* lights = top.find("lights")) {
    if (!lights->is_array()) top.fail("lights", "expected an array, got " + describe(*lights));
    for (size_t i = 0; i < lights->size(); ++i)
      scene.lights.push_back(read_light((*lights)[i], "lights[" + std::to_string(i) + "]", path, scene.used_types));
  }

  const Json& shapes = top.get("shapes");
  if (!shapes.is_array()) top.fail("shapes", "expected an array, got " + describe(shapes));
  SceneBuilder builder(scene, std::filesystem::path(path).parent_path().string(), textures);
  for (size_t i = 0; i < shapes.size(); ++i)
    builder.add_shape(shapes[i], "shapes[" + std::to_string(i) + "]", material_ids, material_types);
  top.finish();

  for (const Primitive& p : scene.primitives) {
    scene.features |= shape_feature(p.kind) | material_feature(scene.materials[p.material].kind);
    if (p.shading >= 0 && scene.triangle_shading[p.shading].has_normals) scene.features |= kFeatureShadingNormals;
  }
  if (!scene.lights.empty()) scene.features |= kFeaturePointLight;
  if (overrides.fresnel)
    for (Material& m : scene.materials)
      if (m.kind == MaterialKind::Dielectric) m.fresnel = *overrides.fresnel;
  scene.offset_scale = ray_offset_scale(scene);
  build_light_table(scene);
  const auto build_start = std::chrono::steady_clock::now();
  build_acceleration(scene);
  scene.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();
  return scene;
}

Scene load_scene(const std::string& path, const RenderOverrides& overrides) {
  return load_scene_text(read_text_file(path, "scene file"), path, overrides);
}

std::vector<std::string> feature_names(uint32_t features) {
  static const char* names[] = {"sphere",     "plane",   "triangle", "quad",        "lambert",   "metal",
                                "dielectric", "phong",   "emissive", "point-light", "thin-lens", "shading-normals",
                                "textures"};
  std::vector<std::string> out;
  for (uint32_t i = 0; i < sizeof names / sizeof names[0]; ++i)
    if (features & (1u << i)) out.push_back(names[i]);
  return out;
}

}  // namespace tracer
