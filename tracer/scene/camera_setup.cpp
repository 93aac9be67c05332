#include "scene/camera_setup.h"

namespace tracer {

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

}  // namespace tracer
