// Builds the kernel Camera from the scene's look-at description.
#pragma once
#include "kernel/camera/camera.h"

namespace tracer {

struct CameraSpec {
  Vec3 from, to, up;
  float vfov_degrees;
  float aperture;        // lens diameter; 0 is a pinhole
  float focus_distance;  // distance to the plane in focus
};

Camera make_camera(const CameraSpec& spec, uint32_t width, uint32_t height);

}  // namespace tracer
