// The CUDA renderer's interface, and the GPU ray queries', in a build that found no nvcc at
// configure time.
#include "render/device_error.h"
#include "render/render_cuda.h"
#include "render/trace_cuda.h"

namespace tracer {

namespace {
[[noreturn]] void no_cuda() {
  throw DeviceUnavailable("this build has no CUDA renderer: CMake found no nvcc when it configured the build");
}
}  // namespace

std::string cuda_device_description() { no_cuda(); }

FilmBuffer render_cuda_film(const Scene&, SampleRange, RenderStats&, CudaRunInfo&) { no_cuda(); }

AdaptiveFilm render_cuda_adaptive(const Scene&, RenderStats&, CudaRunInfo&) { no_cuda(); }

Image render_cuda(const Scene&, RenderStats&, CudaRunInfo&) { no_cuda(); }

struct CudaRayTracer::Device {};

CudaRayTracer::CudaRayTracer(const Scene&, bool) { no_cuda(); }

CudaRayTracer::~CudaRayTracer() = default;

const char* CudaRayTracer::variant() const { no_cuda(); }

double CudaRayTracer::closest(const std::vector<Ray>&, std::vector<Hit>&, uint32_t) { no_cuda(); }

double CudaRayTracer::any(const std::vector<Ray>&, const std::vector<float>&, std::vector<uint8_t>&, uint32_t) {
  no_cuda();
}

}  // namespace tracer
