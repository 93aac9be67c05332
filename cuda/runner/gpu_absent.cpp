// The GPU entry points of a build without CUDA (no nvcc, or TRACER_WITH_CUDA=OFF): each says
// so, and the runner's `--device cpu` still runs every bundle and parity case.
#include <string>

#include "gpu_adaptive.h"
#include "gpu_film.h"
#include "lbvh_gpu.h"
#include "parity/parity_gpu.h"
#include "render/cuda_absent_reason.h"
#include "render/device_error.h"
#include "render/trace_cuda.h"

namespace tracer {

namespace {
[[noreturn]] void no_cuda() { throw DeviceUnavailable(std::string("this build has no CUDA: ") + kCudaAbsentReason); }
}  // namespace

GpuFilm render_film_on_gpu(const SceneArrays&, const SceneView&, SampleRange, const std::string&) { no_cuda(); }
GpuAdaptiveFilm render_adaptive_on_gpu(const SceneArrays&, const SceneView&, const std::string&) { no_cuda(); }
GpuLbvh build_lbvh_on_gpu(const LbvhInput&) { no_cuda(); }
std::string describe_render_kernel() { no_cuda(); }
std::string describe_stream_kernels() { no_cuda(); }

struct CudaRayTracer::Device {};
CudaRayTracer::CudaRayTracer(const SceneArrays&, const SceneView&, DeviceBvh) { no_cuda(); }
CudaRayTracer::~CudaRayTracer() = default;
const char* CudaRayTracer::variant() const { no_cuda(); }
double CudaRayTracer::closest(const std::vector<Ray>&, std::vector<Hit>&, uint32_t, std::optional<RayOrderFrame>) {
  no_cuda();
}
double CudaRayTracer::any(const std::vector<Ray>&, const std::vector<float>&, std::vector<uint8_t>&, uint32_t,
                          std::optional<RayOrderFrame>) {
  no_cuda();
}
double CudaRayTracer::sort(const std::vector<Ray>&, const RayOrderFrame&, uint32_t) { no_cuda(); }

namespace parity {
std::string gpu_device() { no_cuda(); }
std::vector<float> gpu_math(MathFunction, const std::vector<float>&, const std::vector<float>&) { no_cuda(); }
std::vector<Philox4> gpu_philox(const std::vector<PhiloxQuery>&) { no_cuda(); }
std::vector<ShapeAnswer> gpu_shapes(const std::vector<ShapeQuery>&) { no_cuda(); }
std::vector<BsdfAnswer> gpu_bsdfs(const std::vector<BsdfQuery>&) { no_cuda(); }
std::vector<AdaptiveAnswer> gpu_adaptive(const std::vector<AdaptiveQuery>&) { no_cuda(); }
std::vector<TraceAnswer> gpu_trace(const SceneArrays&, const SceneView&, const std::vector<Ray>&) { no_cuda(); }
std::vector<SampleAnswer> gpu_samples(const SceneArrays&, const SceneView&) { no_cuda(); }
std::vector<Vec3> gpu_stream_samples(const SceneArrays&, const SceneView&) { no_cuda(); }
}  // namespace parity

}  // namespace tracer
