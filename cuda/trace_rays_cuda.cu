// `tracer bench rays --device cuda` and `tracer-gpu bench`'s rays table (render/trace_cuda.h): rays traced by the
// stream schedule's closest-hit and shadow kernels over the scene's arrays on the device. The shadow stage is the path
// tracer's: it adds a ray's contribution to its radiance when the light is visible, so each ray carries a contribution
// of 1 and its radiance says whether it was occluded.
#include <algorithm>

#include "cuda_device.h"
#include "cuda_event.h"
#include "device_scene.h"
#include "gpu_stream.h"
#include "kernel/accel/trace_variants.h"
#include "ray_order_gpu.h"
#include "render/trace_cuda.h"

namespace tracer {

namespace {

SceneView path_view(SceneView view) {
  view.settings.integrator = IntegratorKind::Path;  // the shadow stage adds to the radiance
  return view;
}

// The rays' origins and directions as device arrays, the layout of the stream's states.
struct DeviceRays {
  DeviceBuffer<Vec3> origin, dir;
  explicit DeviceRays(const std::vector<Ray>& rays) {
    std::vector<Vec3> o(rays.size()), d(rays.size());
    for (size_t i = 0; i < rays.size(); ++i) o[i] = rays[i].origin, d[i] = rays[i].dir;
    origin = DeviceBuffer<Vec3>(o);
    dir = DeviceBuffer<Vec3>(d);
  }
};

std::vector<uint32_t> identity_queue(size_t n) {
  std::vector<uint32_t> queue(n);
  for (size_t i = 0; i < n; ++i) queue[i] = static_cast<uint32_t>(i);
  return queue;
}

// The median time of `repeats` runs of timed() (CUDA events around what it queues), each
// after reset(), untimed.
template <class Timed, class Reset>
double median_time(uint32_t repeats, Timed&& timed, Reset&& reset) {
  std::vector<double> times;
  for (uint32_t r = 0; r < repeats; ++r) {
    reset();
    const CudaEvent start, stop;
    TRACER_CUDA_CHECK(cudaEventRecord(start.event));
    timed();
    TRACER_CUDA_CHECK(cudaEventRecord(stop.event));
    times.push_back(seconds_between(start, stop));
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

// The median time of `repeats` launches of `stage` over the n states of `queue`, each after
// reset(); with a `sorted` frame, the queue is sorted by the rays' keys (origin and dir) first,
// in the timed part.
template <class Reset>
double median_trace_time(const SceneView& view, StreamStage stage, const StreamStates& st, const Vec3* origin,
                         const Vec3* dir, const uint32_t* queue, size_t n, uint32_t repeats,
                         const std::optional<RayOrderFrame>& sorted, Reset&& reset) {
  std::optional<GpuRaySorter> sorter;
  if (sorted) sorter.emplace(n);
  return median_time(
      repeats,
      [&] { launch_trace_stage(view, stage, st, sorted ? sorter->sort(*sorted, origin, dir, queue, n) : queue, n); },
      reset);
}

}  // namespace

struct CudaRayTracer::Device {
  cudaDeviceProp prop;  // selected before the scene is uploaded
  DeviceScene scene;
  Device(const SceneArrays& arrays, const SceneView& view, DeviceBvh tree)
      : prop(select_cuda_device()), scene(arrays, path_view(view), tree) {}
};

CudaRayTracer::CudaRayTracer(const SceneArrays& arrays, const SceneView& view, DeviceBvh tree)
    : device_(std::make_unique<Device>(arrays, view, tree)) {}

const char* CudaRayTracer::variant() const {
  const SceneView& view = device_->scene.view();
  return trace_variant_name(
      trace_variant_of(view.features, view.settings, view.wide_node_count != 0, view.bvh_pair_count != 0));
}

CudaRayTracer::~CudaRayTracer() = default;

double CudaRayTracer::closest(const std::vector<Ray>& rays, std::vector<Hit>& hits, uint32_t repeats,
                              std::optional<RayOrderFrame> sorted) {
  const size_t n = rays.size();
  const DeviceRays d_rays(rays);
  const DeviceBuffer<uint32_t> queue(identity_queue(n));
  DeviceBuffer<Hit> d_hit(n);
  StreamStates st{};
  st.origin = d_rays.origin.get();
  st.dir = d_rays.dir.get();
  st.hit = d_hit.get();
  const double seconds = median_trace_time(device_->scene.view(), StreamStage::Closest, st, st.origin, st.dir,
                                           queue.get(), n, repeats, sorted, [] {});
  hits = d_hit.download();
  return seconds;
}

double CudaRayTracer::any(const std::vector<Ray>& rays, const std::vector<float>& tmax, std::vector<uint8_t>& occluded,
                          uint32_t repeats, std::optional<RayOrderFrame> sorted) {
  const size_t n = rays.size();
  const DeviceRays d_rays(rays);
  const DeviceBuffer<Vec3> contribution(std::vector<Vec3>(n, Vec3{1.0f, 0.0f, 0.0f}));
  const DeviceBuffer<float> d_tmax(tmax);
  const DeviceBuffer<uint32_t> emitter(std::vector<uint32_t>(n, kNoHit)), queue(identity_queue(n));
  DeviceBuffer<Vec3> radiance(n);
  StreamStates st{};
  st.shadow_origin = d_rays.origin.get();
  st.shadow_dir = d_rays.dir.get();
  st.shadow_tmax = d_tmax.get();
  st.shadow_emitter = emitter.get();
  st.shadow_contribution = contribution.get();
  st.radiance = radiance.get();
  const double seconds = median_trace_time(device_->scene.view(), StreamStage::Shadow, st, st.shadow_origin,
                                           st.shadow_dir, queue.get(), n, repeats, sorted, [&] { radiance.zero(); });
  const std::vector<Vec3> seen = radiance.download();
  occluded.resize(n);
  for (size_t i = 0; i < n; ++i) occluded[i] = seen[i].x == 0.0f ? 1 : 0;
  return seconds;
}

double CudaRayTracer::sort(const std::vector<Ray>& rays, const RayOrderFrame& frame, uint32_t repeats) {
  const size_t n = rays.size();
  const DeviceRays d_rays(rays);
  const DeviceBuffer<uint32_t> queue(identity_queue(n));
  GpuRaySorter sorter(n);
  return median_time(
      repeats, [&] { sorter.sort(frame, d_rays.origin.get(), d_rays.dir.get(), queue.get(), n); }, [] {});
}

}  // namespace tracer
