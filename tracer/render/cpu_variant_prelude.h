// The global-scope headers of a CPU kernel variant's files (cpu_kernel_variant.cpp,
// cpu_stream_variant.cpp, bench/ray_recorder.cpp), included before the kernel's headers are
// included inside the variant's namespace.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>     // GLM (the kernel's Vec3 and frames) at global scope; GLM_FORCE_INLINE
#include <glm/gtc/type_ptr.hpp>  // keeps each variant's uses inside its own instruction set
#include <glm/mat3x3.hpp>        // (CMakeLists.txt)
#include <glm/vec3.hpp>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "render/cpu_kernel.h"
