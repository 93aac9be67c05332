// Compiles every tracer/kernel header as CUDA device code and instantiates each entry
// point in a kernel, so a host-only construct in kernel code breaks the build. Nothing
// launches this kernel; the CUDA renderer itself is a later issue.
#include "kernel/render_pixel.h"

namespace tracer {

__global__ void kernel_device_check(const SceneView scene, float* out, RayCounts* counts) {
  const uint32_t x = blockIdx.x * blockDim.x + threadIdx.x;
  const float f = static_cast<float>(x);
  out[0] = det_sin(f) + det_cos(f) + det_tan(f) + det_asin(f) + det_acos(f) + det_atan2(f, 1.0f) +
           det_exp(f) + det_log(f) + det_pow(f, 2.0f);
  const PixelResult r = render_pixel(scene, x, 0, *counts);
  out[1] = r.value.x;
  const Ray ray = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};
  out[2] = trace_any(scene, ray, 1.0f) ? 1.0f : 0.0f;
}

}  // namespace tracer
