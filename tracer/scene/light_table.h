// The path integrator's light table (kernel/light/light.h): every declared light, every
// emissive sphere, quad and triangle and a sampled environment, chosen with probability
// proportional to its power (each kind's header says how it is computed; for the environment,
// its radiance's luminance integrated over the sphere times pi r^2, r the radius of the
// scene's bounds).
// Emissive planes have infinite area and are left out: only BSDF samples find them. With
// render.mirror_images (path, nee on, a shape light) it also lists every planar mirror
// (kernel/shading/mirror_images.h).
#pragma once
#include "scene/scene.h"

namespace tracer {

// Fills light_table, light_of_prim, sky_cells, environment_light and mirror_prims.
void build_light_table(Scene& scene);

}  // namespace tracer
