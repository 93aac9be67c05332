// The scene file's `camera` key (a look-at description) and the kernel Camera built from it.
#pragma once
#include <string>

#include "io/json_reader.h"
#include "kernel/camera/camera.h"

namespace tracer {

struct CameraSpec {
  Vec3 from, to, up;
  float vfov_degrees;
  float aperture;        // lens diameter; 0 is a pinhole
  float focus_distance;  // distance to the plane in focus
};

// Reads and checks the `camera` object; errors name the file and key.
CameraSpec read_camera_spec(const Json& value, const std::string& file);

Camera make_camera(const CameraSpec& spec, uint32_t width, uint32_t height);

}  // namespace tracer
