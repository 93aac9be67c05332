// Pinhole and thin-lens camera. The host fills the plain struct once (tracer/scene/camera_setup.cpp);
// kernel code maps a film position and a lens sample to a unit-direction ray.
#pragma once
#include "kernel/base/detmath.h"
#include "kernel/base/vec3.h"

namespace tracer {

struct Camera {
  Vec3 origin;
  Vec3 focal_top_left;  // point on the focus plane seen by the image's top-left corner
  Vec3 pixel_dx;        // focus-plane step of one pixel to the right
  Vec3 pixel_dy;        // focus-plane step of one pixel down
  Vec3 lens_u, lens_v;  // unit lens axes (camera right and up)
  float lens_radius;    // 0: pinhole
};

// Film position (fx, fy) in pixels from the top-left corner; (lu, lv) uniform in [0,1)^2
// pick a point on the lens disk by the polar map r = R sqrt(lu), phi = 2 pi lv.
TRACER_HD Ray camera_ray(const Camera& cam, float fx, float fy, float lu, float lv) {
  const Vec3 target = cam.focal_top_left + cam.pixel_dx * fx + cam.pixel_dy * fy;
  Vec3 origin = cam.origin;
  if (cam.lens_radius > 0.0f) {
    const float r = cam.lens_radius * det_sqrt(lu);
    float sin_phi, cos_phi;
    det_sincos(2.0f * kPi * lv, sin_phi, cos_phi);
    origin = origin + cam.lens_u * (r * cos_phi) + cam.lens_v * (r * sin_phi);
  }
  return {origin, normalize(target - origin)};
}

}  // namespace tracer
