// Why a build has no CUDA renderer, in the errors of render_cuda_absent.cpp and gpu_absent.cpp:
// CMakeLists.txt defines TRACER_CUDA_SWITCHED_OFF for both where TRACER_WITH_CUDA is OFF.
#pragma once

namespace tracer {

#ifdef TRACER_CUDA_SWITCHED_OFF
constexpr const char kCudaAbsentReason[] =
    "it was configured with TRACER_WITH_CUDA=OFF (as ci/quickstart.sh does on a machine without an NVIDIA GPU); "
    "`cmake --preset default && cmake --build build` adds the CUDA renderer";
#else
constexpr const char kCudaAbsentReason[] = "CMake found no nvcc when it configured the build";
#endif

}  // namespace tracer
