// The path integrator's light table (kernel/light/light.h): every declared light, every
// emissive sphere, quad and triangle and a sampled environment, chosen with probability
// proportional to its power (each kind's header says how it is computed; for the environment,
// its radiance's luminance integrated over the sphere times pi r^2, r the radius of the
// scene's bounds).
// Emissive planes have infinite area and are left out: only BSDF samples find them.
#pragma once
#include "scene/scene.h"

namespace tracer {

// Fills light_table, light_of_prim, sky_cells and environment_light.
void build_light_table(Scene& scene);

// The planar mirrors whose light images the path tracer samples (render.mirror_images: path, nee
// on, a shape light in the table; kernel/shading/mirror_images.h) into mirror_prims, and the
// scene's kFeatureMirrorImages with them, so that it runs the kernel with their code. The setting
// is left as given: a scene with none to sample runs the kernel without the feature and
// allocates no stream arrays for it.
void build_mirror_list(Scene& scene);

}  // namespace tracer
