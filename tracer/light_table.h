// The path integrator's light table (kernel/light_sampling.h): every point light and every
// emissive sphere, quad and triangle, chosen with probability proportional to its power
// (luminance of the intensity times 4 pi for a point light; of the radiance times pi times
// the area, twice for two-sided emitters, for a shape). Emissive planes have infinite area
// and are left out: only BSDF samples find them.
#pragma once
#include "scene.h"

namespace tracer {

void build_light_table(Scene& scene);  // fills scene.light_table and scene.light_of_prim

}  // namespace tracer
