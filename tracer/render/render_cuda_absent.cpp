// The CUDA renderer's interface in a build without it: configured with TRACER_WITH_CUDA=OFF, or
// no nvcc found at configure time (the GPU ray queries' is in cuda/runner/gpu_absent.cpp).
#include <string>

#include "render/cuda_absent_reason.h"
#include "render/device_error.h"
#include "render/render_cuda.h"

namespace tracer {

namespace {
[[noreturn]] void no_cuda() {
  throw DeviceUnavailable(std::string("this build has no CUDA renderer: ") + kCudaAbsentReason);
}
}  // namespace

std::string cuda_device_description() { no_cuda(); }

FilmBuffer render_cuda_film(const Scene&, SampleRange, RenderStats&, CudaRunInfo&) { no_cuda(); }

AdaptiveFilm render_cuda_adaptive(const Scene&, RenderStats&, CudaRunInfo&) { no_cuda(); }

Image render_cuda(const Scene&, RenderStats&, CudaRunInfo&) { no_cuda(); }

}  // namespace tracer
