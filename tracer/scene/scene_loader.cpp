#include "scene/scene_loader.h"

#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "accel/acceleration.h"
#include "accel/bounds.h"
#include "io/json_reader.h"
#include "io/out_of_memory.h"
#include "io/text_file.h"
#include "scene/camera_setup.h"
#include "scene/gltf_file.h"
#include "scene/light_reader.h"
#include "scene/light_table.h"
#include "scene/material_reader.h"
#include "scene/settings_reader.h"
#include "scene/shape_reader.h"
#include "scene/texture_loader.h"

namespace tracer {
namespace {

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
    if (p.kind == ShapeKind::Plane)
      b.grow(p.a);
    else
      b.grow(primitive_bounds(p));
  }
  b.grow(scene.camera.origin);
  for (const Light& l : scene.lights) b.grow(l.position);
  const Vec3 d = b.hi - b.lo;
  const float size = std::max(d.x, std::max(d.y, d.z));
  float scale = 1.0f;
  while (scale * 0.5f >= size && scale > 0x1p-100f) scale *= 0.5f;
  return scale;
}

// The structure's arrays become the scene's; its summary goes to the load report.
void install_acceleration(Acceleration a, Scene& scene) {
  scene.report.accel = acceleration_summary(scene.settings.accel, a);
  scene.report.accel_bytes = acceleration_bytes(a);
  scene.bounded = std::move(a.bounded);
  scene.unbounded = std::move(a.unbounded);
  scene.bvh_nodes = std::move(a.bvh_nodes);
  scene.wide_nodes = std::move(a.wide.nodes);
  scene.triangle_blocks = std::move(a.wide.blocks);
  scene.kd_nodes = std::move(a.kd.nodes);
  scene.kd_prims = std::move(a.kd.prims);
  scene.kd_lo = a.kd.lo, scene.kd_hi = a.kd.hi, scene.kd_pad = a.kd.pad;
  scene.grid = a.grid.info;
  scene.grid_cell_start = std::move(a.grid.cell_start);
  scene.grid_prims = std::move(a.grid.prims);
}

Scene load_scene_unguarded(const std::string& text, const std::string& path, const RenderOverrides& overrides) {
  Scene scene;
  scene.file = path;
  const Json root = parse_json_text(text, path);
  JsonObject top(root, "", path);
  const std::string format = top.string("format");
  if (format != "tracer-scene/1") top.fail("format", "expected \"tracer-scene/1\", got \"" + format + "\"");

  if (overrides.camera || overrides.background)
    throw InputError(path + ": command line " + (overrides.camera ? "--camera" : "--background") +
                     ": for glTF files; a JSON scene has its own camera and background keys");
  scene.settings = read_settings(top.find("render"), top.get("film"), path, overrides, scene.report.used_types);
  const CameraSpec camera = read_camera_spec(top.get("camera"), path);
  scene.camera_spec = camera;
  scene.camera = make_camera(camera, scene.settings.width, scene.settings.height);
  if (camera.aperture > 0.0f) scene.features |= kFeatureThinLens;
  TextureLoader textures(scene, std::filesystem::path(path).parent_path().string());
  std::string background_type;
  scene.background = read_background(top.find("background"), path, background_type, textures);
  scene.report.used_types.insert("background:" + background_type);
  scene.ambient = top.find("ambient") ? top.color("ambient") : Vec3{0, 0, 0};

  std::map<std::string, uint32_t> material_ids;
  std::vector<std::string> material_types;
  JsonObject materials(top.get("materials"), "materials", path);
  for (const auto& item : top.get("materials").items()) {
    materials.find(item.key());
    material_ids[item.key()] = static_cast<uint32_t>(scene.materials.size());
    material_types.emplace_back();
    scene.materials.push_back(
        read_material(item.value(), materials.child(item.key()), path, material_types.back(), textures));
    scene.material_names.push_back(item.key());
  }

  if (const Json* lights = top.find("lights")) {
    if (!lights->is_array()) top.fail("lights", "expected an array, got " + describe(*lights));
    for (size_t i = 0; i < lights->size(); ++i)
      scene.lights.push_back(
          read_light((*lights)[i], "lights[" + std::to_string(i) + "]", path, scene.report.used_types));
  }

  read_shapes(top.get("shapes"), path, material_ids, material_types, textures, scene);
  top.finish();

  finish_scene(scene, overrides);
  return scene;
}

}  // namespace

void finish_scene(Scene& scene, const RenderOverrides& overrides) {
  if (overrides.environment) {
    TextureLoader textures(scene, "");
    const uint32_t map = textures.environment_map("command line --environment", *overrides.environment);
    set_environment(scene.background, map, 0.0, 1.0);
    auto& types = scene.report.used_types;
    for (auto it = types.begin(); it != types.end();) it = it->rfind("background:", 0) == 0 ? types.erase(it) : ++it;
    types.insert("background:environment");
  }
  for (const Primitive& p : scene.primitives) {
    const Material& m = scene.materials[p.material];
    scene.features |= shape_feature(p.kind) | material_feature(m.kind);
    if (m.alpha_mode != AlphaMode::Opaque) {
      scene.features |= kFeatureAlpha;
      scene.report.used_types.insert(m.alpha_mode == AlphaMode::Mask ? "alpha:mask" : "alpha:blend");
    }
    if (p.shading >= 0 && scene.triangle_shading[p.shading].has_normals) scene.features |= kFeatureShadingNormals;
  }
  if (!scene.lights.empty()) scene.features |= kFeatureDeclaredLights;
  if (overrides.fresnel)
    for (Material& m : scene.materials)
      if (m.kind == MaterialKind::Dielectric) m.fresnel = *overrides.fresnel;
  scene.offset_scale = ray_offset_scale(scene);
  build_light_table(scene);
  build_mirror_list(scene);
  const auto build_start = std::chrono::steady_clock::now();
  install_acceleration(build_acceleration(scene.settings.accel, scene.primitives, scene.settings.grid_resolution),
                       scene);
  scene.report.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - build_start).count();
}

void place_camera(Scene& scene, const CameraSpec& spec) {
  scene.camera_spec = spec;
  scene.camera = make_camera(spec, scene.settings.width, scene.settings.height);
  scene.offset_scale = ray_offset_scale(scene);
}

Scene load_scene_text(const std::string& text, const std::string& path, const RenderOverrides& overrides) {
  return naming_file_when_out_of_memory(path, "loading the scene, its meshes and textures and building its accelerator",
                                        [&] {
                                          return is_gltf_path(path) ? load_gltf_scene(text, path, overrides)
                                                                    : load_scene_unguarded(text, path, overrides);
                                        });
}

Scene load_scene(const std::string& path, const RenderOverrides& overrides) {
  return load_scene_text(read_text_file(path, "scene file", is_gltf_path(path) ? kMaxGltfFileBytes : UINT64_MAX), path,
                         overrides);
}

std::vector<std::string> feature_names(uint32_t features) {
  static const char* names[] = {"sphere",   "plane",           "triangle",      "quad",
                                "lambert",  "metal",           "dielectric",    "phong",
                                "emissive", "declared-lights", "thin-lens",     "shading-normals",
                                "textures", "microfacet",      "mirror-images", "alpha"};
  std::vector<std::string> out;
  for (uint32_t i = 0; i < sizeof names / sizeof names[0]; ++i)
    if (features & (1u << i)) out.push_back(names[i]);
  return out;
}

}  // namespace tracer
