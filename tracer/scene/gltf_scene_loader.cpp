// `tracer render model.glb`: a glTF file as the whole scene (docs/gltf.md, "Rendering a glTF
// file"). Render settings: the glTF defaults below under the command line's options; the
// camera: --camera NAME|INDEX, else the first a node places, else one framing the bounds.
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "accel/bounds.h"
#include "io/input_error.h"
#include "kernel/base/detmath.h"
#include "options/work_limits.h"
#include "scene/gltf_scene.h"
#include "scene/scene_loader.h"
#include "scene/settings_reader.h"

namespace tracer {
namespace {

constexpr uint32_t kDefaultWidth = 640;
constexpr float kFramingVfov = 40.0f;  // degrees, the framing camera's

// The camera --camera names: a camera's index in the file's cameras, or its (or its node's) name.
const GltfCamera& chosen_camera(const GltfContents& contents, const std::string& choice, const std::string& path) {
  const bool numeric = !choice.empty() && choice.find_first_not_of("0123456789") == std::string::npos;
  for (const GltfCamera& c : contents.cameras)
    if ((numeric && choice.size() < 9 && c.index == std::atoi(choice.c_str())) || (!numeric && c.name == choice))
      return c;
  std::string known;
  for (const GltfCamera& c : contents.cameras)
    known += (known.empty() ? "" : ", ") + std::to_string(c.index) + (c.name.empty() ? "" : " \"" + c.name + "\"");
  throw InputError(path + ": command line --camera: no perspective camera \"" + choice + "\" in the file (" +
                   (known.empty() ? "it places none" : "it places " + known) + ")");
}

// A camera on the +z side of the bounds' centre, looking down -z (glTF's front), far enough
// that the bounding sphere fits the vertical field of view.
CameraSpec framing_camera(const Scene& scene) {
  Bounds b;
  for (const Primitive& p : scene.primitives) b.grow(primitive_bounds(p));
  const Vec3 centre = (b.lo + b.hi) * 0.5f;
  const float radius = std::max(length(b.hi - b.lo) * 0.5f, 1e-3f);
  const float distance = radius / det_sin(kFramingVfov * 0.5f * (kPi / 180.0f)) * 1.05f;
  CameraSpec spec{};
  spec.from = centre + Vec3{0.0f, 0.0f, distance};
  spec.to = centre;
  spec.up = {0, 1, 0};
  spec.vfov_degrees = kFramingVfov;
  spec.aperture = 0.0f;
  spec.focus_distance = distance;
  return spec;
}

}  // namespace

Scene load_gltf_scene(const std::string& bytes, const std::string& path, const RenderOverrides& overrides) {
  Scene scene;
  scene.file = path;
  const GltfFile file = read_gltf_file(bytes, path);
  const GltfContents contents = add_gltf_file(file, Transform{}, true, scene);
  if (scene.primitives.empty()) {
    std::string left_out;
    for (size_t i = 0; i < contents.ignored.size() && i < 3; ++i) left_out += "; left out: " + contents.ignored[i];
    throw InputError(path + ": its default scene places no triangles with an area (nothing to draw)" + left_out);
  }

  const GltfCamera* camera = nullptr;
  if (overrides.camera)
    camera = &chosen_camera(contents, *overrides.camera, path);
  else if (!contents.cameras.empty())
    camera = &contents.cameras.front();

  // The film: the command line's size, else 640 wide (or --width) at the camera's aspect
  // ratio, 4:3 when it gives none.
  Json film = Json::object();
  const double width = overrides.width ? *overrides.width : kDefaultWidth;
  const double aspect = camera && camera->aspect > 0.0f ? camera->aspect : 4.0 / 3.0;
  film["width"] = kDefaultWidth;
  film["height"] = std::max<int64_t>(1, std::min<int64_t>(std::llround(width / aspect), kMaxResolution));
  const Json render = {{"integrator", "path"}, {"spp", 64}, {"sampler", "sobol"}, {"max_depth", 8}};
  scene.settings = read_settings(&render, film, path, overrides, scene.report.used_types);

  CameraSpec spec = camera ? camera->spec : framing_camera(scene);
  spec.focus_distance = length(spec.to - spec.from);
  scene.camera = make_camera(spec, scene.settings.width, scene.settings.height);

  // No lights of its own (no point light, nothing emits): a white sky lights it.
  bool emits = !scene.lights.empty();
  for (const Material& m : scene.materials) emits = emits || m.kind == MaterialKind::Emissive;
  const Vec3 sky = overrides.background ? *overrides.background : emits ? Vec3{0, 0, 0} : Vec3{1, 1, 1};
  scene.background = {BackgroundKind::Constant,
                      sky,
                      {0, 0, 0},
                      {kNoTexture, kNoTexture, kNoTexture, kNoTexture, kNoTexture, kNoTexture}};
  scene.report.used_types.insert("background:constant");
  scene.report.shape_counts["gltf"] = 1;

  auto& info = scene.report.gltf;
  info.push_back("meshes " + std::to_string(contents.meshes) + ", triangles " + std::to_string(contents.triangles) +
                 ", materials " + std::to_string(contents.materials) + ", textures " +
                 std::to_string(contents.textures) + ", cameras " + std::to_string(contents.cameras.size()) +
                 ", point lights " + std::to_string(contents.lights));
  info.push_back(camera ? "camera " + std::to_string(camera->index) +
                              (camera->name.empty() ? "" : " \"" + camera->name + "\"")
                        : std::string("camera (none in the file: one framing the bounds)"));
  for (const std::string& s : contents.ignored) info.push_back("ignored " + s);
  finish_scene(scene, overrides);
  return scene;
}

}  // namespace tracer
