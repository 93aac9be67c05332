// Ray queries on the GPU, for `tracer bench rays --device cuda` and `tracer-gpu bench`'s rays
// table (cuda/trace_rays_cuda.cu): the scene's arrays on the device and a buffer of rays traced
// by the stream schedule's closest-hit and shadow kernels, the scene's trace variant
// (kernel/accel/trace_variants.h), each launch timed with CUDA events; `repeats` is at least 1.
// `tree` says which of a bvh scene's trees goes to the device (render/device_bvh.h): with the
// 8-wide one its rays run on the wide_bvh_triangles variant. With a `sorted` frame, each launch
// is preceded by a sort of the set's queue by its rays' keys in that frame (cuda/ray_order_gpu.h),
// timed with it. A build without nvcc links cuda/runner/gpu_absent.cpp, whose
// constructor raises DeviceUnavailable.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "kernel/accel/primitive_hit.h"
#include "kernel/geom/ray_order_key.h"
#include "render/device_bvh.h"
#include "scene/scene_arrays.h"

namespace tracer {

class CudaRayTracer {
 public:
  // Uploads the arrays (`view` gives the scalars); DeviceUnavailable when there is no usable GPU.
  CudaRayTracer(const SceneArrays& arrays, const SceneView& view, DeviceBvh tree);
  ~CudaRayTracer();
  CudaRayTracer(const CudaRayTracer&) = delete;
  CudaRayTracer& operator=(const CudaRayTracer&) = delete;

  // The closest hit of each ray (t in (0, inf)); the median kernel time of `repeats` launches, in seconds.
  double closest(const std::vector<Ray>& rays, std::vector<Hit>& hits, uint32_t repeats,
                 std::optional<RayOrderFrame> sorted = std::nullopt);

  // The trace variant the rays run on (kernel/accel/trace_variants.h).
  const char* variant() const;

  // Whether anything lies in (0, tmax[i]) along rays[i]; the median kernel time of `repeats` launches.
  double any(const std::vector<Ray>& rays, const std::vector<float>& tmax, std::vector<uint8_t>& occluded,
             uint32_t repeats, std::optional<RayOrderFrame> sorted = std::nullopt);

  // The median time of `repeats` sorts of the rays' queue by their keys in `frame`, alone.
  double sort(const std::vector<Ray>& rays, const RayOrderFrame& frame, uint32_t repeats);

 private:
  struct Device;
  std::unique_ptr<Device> device_;
};

}  // namespace tracer
