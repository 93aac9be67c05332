// The CPU kernel variants this CPU runs that may render a scene using `features`: every
// feature set that holds them, on every instruction set this CPU has.
#pragma once
#include <string>
#include <vector>

#include "render/cpu_kernel.h"

namespace tracer::test {

inline std::vector<const CpuKernelVariant*> variants_for(uint32_t features) {
  std::vector<const CpuKernelVariant*> list;
  for (const CpuKernelVariant* generic : cpu_kernels_per_isa(features, true))
    for (const CpuKernelVariant* v : cpu_kernel_variants())
      if (v->isa == std::string(generic->isa) && (v->features & features) == features) list.push_back(v);
  return list;
}

}  // namespace tracer::test
