// The CUDA renderer's interface in a build that found no nvcc at configure time (the GPU ray
// queries' is in cuda/runner/gpu_absent.cpp).
#include "render/device_error.h"
#include "render/render_cuda.h"

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

}  // namespace tracer
