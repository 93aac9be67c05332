// `tracer render model.glb`: a glTF file as the whole scene (docs/gltf.md, "Rendering a glTF
// file"). Render settings: the glTF defaults below under the command line's options; the
// camera: --camera NAME|INDEX, else the first a node places, else one framing the model.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "accel/bounds.h"
#include "io/input_error.h"
#include "kernel/base/detmath.h"
#include "options/work_limits.h"
#include "scene/gltf_scene.h"
#include "scene/light_reader.h"
#include "scene/scene_loader.h"
#include "scene/settings_reader.h"

namespace tracer {
namespace {

constexpr uint32_t kDefaultWidth = 640;
constexpr float kFramingVfov = 40.0f;       // degrees, the framing camera's
constexpr float kFramingElevation = 15.0f;  // degrees above the horizontal, seen from +z
constexpr float kFramingFill = 0.9f;        // of the frame's width or height, whichever binds

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

// The default camera: it looks from the front (+z, glTF's front) and kFramingElevation above,
// along `forward`, from the nearest distance D (and sideways offset a, b) that puts every
// vertex inside the middle kFramingFill of the frame. A vertex at (x, y, z) along the
// view's right, up and forward axes projects to (x - a) / (D + z) horizontally, which lies in
// [-T, T] for T = tan(hfov / 2) kFramingFill when x - T (D + z) <= a <= x + T (D + z): such an
// a exists for every pair of vertices once D >= (max(x / T - z) + max(-x / T - z)) / 2, and
// the middle of the interval then centres the model. Likewise vertically.
CameraSpec framing_camera(const Scene& scene, double aspect) {
  const Bounds b = bounds_of_primitives(scene.primitives.data(), scene.primitives.size());
  const Vec3 centre = (b.lo + b.hi) * 0.5f;
  const float elevation = kFramingElevation * (kPi / 180.0f);
  const Vec3 forward = {0.0f, -det_sin(elevation), -det_cos(elevation)}, up_axis = {0.0f, 1.0f, 0.0f};
  const Vec3 right = normalize(cross(forward, up_axis)), up = cross(right, forward);
  const double tan_y = det_tan(kFramingVfov * 0.5f * (kPi / 180.0f)) * kFramingFill, tan_x = tan_y * aspect;
  struct Extent {
    double tan, plus = -1e300, minus = -1e300;  // max(x / T - z), max(-x / T - z)
    double low = -1e300, high = 1e300;          // the offsets a that fit, for the distance found
  } across{tan_x}, upward{tan_y};
  double nearest = -1e300;  // max(-z): D must exceed it
  std::vector<Vec3> corners;
  for (const Primitive& p : scene.primitives) corners.insert(corners.end(), {p.a, p.b, p.c});  // triangles only
  for (const Vec3& c : corners) {
    const Vec3 d = c - centre;
    const double x = dot(d, right), y = dot(d, up), z = dot(d, forward);
    across.plus = std::max(across.plus, x / tan_x - z), across.minus = std::max(across.minus, -x / tan_x - z);
    upward.plus = std::max(upward.plus, y / tan_y - z), upward.minus = std::max(upward.minus, -y / tan_y - z);
    nearest = std::max(nearest, -z);
  }
  const double extent = std::max<double>(length(b.hi - b.lo), 1e-3);
  const double distance =
      std::max({(across.plus + across.minus) / 2, (upward.plus + upward.minus) / 2, nearest + 1e-3 * extent});
  for (const Vec3& c : corners) {
    const Vec3 d = c - centre;
    const double z = distance + dot(d, forward);
    for (auto [e, v] : {std::pair{&across, double(dot(d, right))}, std::pair{&upward, double(dot(d, up))}})
      e->low = std::max(e->low, v - e->tan * z), e->high = std::min(e->high, v + e->tan * z);
  }
  const float a = static_cast<float>((across.low + across.high) / 2),
              h = static_cast<float>((upward.low + upward.high) / 2);
  CameraSpec spec{};
  spec.from = centre + right * a + up * h - forward * static_cast<float>(distance);
  spec.to = spec.from + forward;
  spec.up = up_axis;
  spec.vfov_degrees = kFramingVfov;
  spec.aperture = 0.0f;
  spec.focus_distance = static_cast<float>(distance);
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

  CameraSpec spec =
      camera ? camera->spec : framing_camera(scene, double(scene.settings.width) / double(scene.settings.height));
  spec.focus_distance = length(spec.to - spec.from);
  scene.camera_spec = spec;
  scene.camera = make_camera(spec, scene.settings.width, scene.settings.height);

  // A white sky of radiance 1 lights it as a viewer's neutral environment does, whatever
  // lights the file has of its own; --background replaces it.
  const Vec3 sky = overrides.background ? *overrides.background : Vec3{1, 1, 1};
  scene.background = constant_background(sky);
  scene.report.used_types.insert("background:constant");
  scene.report.shape_counts["gltf"] = 1;

  auto& info = scene.report.gltf;
  info.push_back("meshes " + std::to_string(contents.meshes) + ", triangles " + std::to_string(contents.triangles) +
                 ", materials " + std::to_string(contents.materials) + ", textures " +
                 std::to_string(contents.textures) + ", cameras " + std::to_string(contents.cameras.size()) +
                 ", lights " + std::to_string(contents.lights));
  const auto triple = [](Vec3 v) {
    char text[96];
    std::snprintf(text, sizeof text, "%.9g,%.9g,%.9g", v.x, v.y, v.z);
    return std::string(text);
  };
  info.push_back(
      camera ? "camera " + std::to_string(camera->index) + (camera->name.empty() ? "" : " \"" + camera->name + "\"")
             : "camera (none in the file: one framing the model) from " + triple(spec.from) + " to " + triple(spec.to) +
                   " up " + triple(spec.up) + " vfov " + std::to_string(int(kFramingVfov)));
  for (const std::string& s : contents.ignored) info.push_back("ignored " + s);
  finish_scene(scene, overrides);
  return scene;
}

}  // namespace tracer
