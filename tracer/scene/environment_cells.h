// The environment light's sampling distribution (kernel/light/environment_light.h and
// equirect_map.h): the map's cells, each weighted by the largest luminance of the filtered map
// over it times its solid angle, as cumulative sums in multiples of 2^-24.
#pragma once
#include "scene/scene.h"

namespace tracer {

// Fills scene.sky_cells and the cell counts for the scene's cube map or equirectangular map;
// returns the integral of luminance over the sphere that the weights estimate (0: the map is
// black and the cells are left empty).
double build_environment_cells(Scene& scene);

}  // namespace tracer
