#include "scene/camera_setup.h"

namespace tracer {

// The basis of glm::lookAt (w opposite the view, u = up x w, v = w x u), built here: lookAt
// normalizes through inversesqrt (a reciprocal and a multiply) where ours divides by the length.
Camera make_camera(const CameraSpec& spec, uint32_t width, uint32_t height) {
  const Vec3 w = normalize(spec.from - spec.to);  // camera looks along -w
  const Vec3 u = normalize(cross(spec.up, w));
  const Vec3 v = cross(w, u);
  const float half_height = det_tan(spec.vfov_degrees * (kPi / 360.0f)) * spec.focus_distance;
  const float half_width = half_height * (static_cast<float>(width) / static_cast<float>(height));
  Camera cam;
  cam.origin = spec.from;
  cam.focal_top_left = spec.from - w * spec.focus_distance - u * half_width + v * half_height;
  cam.pixel_dx = u * (2.0f * half_width / static_cast<float>(width));
  cam.pixel_dy = v * (-2.0f * half_height / static_cast<float>(height));
  cam.lens_u = u;
  cam.lens_v = v;
  cam.lens_radius = 0.5f * spec.aperture;
  return cam;
}

CameraSpec read_camera_spec(const Json& value, const std::string& file) {
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
  if (!(length(cross(spec.up, spec.to - spec.from)) > 0.0f))
    obj.fail("up", "must not be parallel to the view direction");
  obj.finish();
  return spec;
}

}  // namespace tracer
