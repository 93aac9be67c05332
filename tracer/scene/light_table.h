// The path integrator's light table (kernel/shading/light_sampling.h): every point light and every
// emissive sphere, quad and triangle, chosen with probability proportional to its power
// (luminance of the intensity times 4 pi for a point light; of the radiance times pi times
// the area, twice for two-sided emitters, for a shape; of the sky's radiance integrated
// over the sphere times pi r^2 for a cube-map sky, r the radius of the scene's bounds).
// Emissive planes have infinite area and are left out: only BSDF samples find them. With
// render.mirror_images (path, nee on, a shape light) it also lists every planar mirror
// (kernel/shading/mirror_images.h).
#pragma once
#include "scene/scene.h"

namespace tracer {

void build_light_table(Scene& scene);  // fills light_table, light_of_prim, sky_cells, sky_light and mirror_prims

}  // namespace tracer
