#include "cli/version_text.h"

#include "build_config.h"
#include "git_commit.h"
#include "render/cpu_kernel.h"

namespace tracer {

std::string version_text() {
  std::string kernels;
  for (const CpuKernelVariant* v : cpu_kernel_variants())
    kernels += (kernels.empty() ? "" : ", ") + cpu_kernel_name(*v);
  std::string isas;
  for (const CpuKernelVariant* v : cpu_kernels_per_isa(0)) isas += (isas.empty() ? "" : ", ") + std::string(v->isa);
  return std::string("tracer ") + TRACER_VERSION + "\ncommit: " + TRACER_GIT_COMMIT + "\ncompiler: " + TRACER_COMPILER +
         "\nCPU kernels: " + kernels + "\nthis CPU runs: " + isas + "\nCUDA renderer: " + TRACER_CUDA_BUILT;
}

}  // namespace tracer
