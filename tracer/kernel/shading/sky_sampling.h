// Importance sampling of a cube-map sky for next-event estimation. The host divides each
// face into n x n cells (at most the face's texels) and gives each cell a probability
// proportional to the largest luminance of the filtered sky over it (found on its grid of
// half-texel steps, where the bilinear filter has its extremes) times its solid angle; the cumulative sums are
// multiples of 2^-24, so the probability of drawing a cell with a 24-bit uniform is exactly its pmf. A direction is
// uniform in its cell on the face (coordinates a, b in [-1, 1] at distance 1), whose solid-angle density is pmf / (4 /
// n^2) * (1 + a^2 + b^2)^(3/2) (dA cos / r^2 = dA / r^3).
#pragma once
#include "kernel/base/float_to_int.h"
#include "kernel/shading/light_sources.h"
#include "kernel/shading/sampling.h"

namespace tracer {

constexpr uint32_t kSkyLight = 0xfffffffeu;  // LightSample::prim of a sky sample

// The unnormalised direction through face coordinates (a, b), the inverse of cube_face().
TRACER_HD Vec3 cube_direction(uint32_t face, float a, float b) {
  switch (face) {
    case 0: return {1.0f, b, a};
    case 1: return {-1.0f, b, -a};
    case 2: return {a, 1.0f, b};
    case 3: return {a, -1.0f, -b};
    case 4: return {-a, b, 1.0f};
    default: return {a, b, -1.0f};
  }
}

// Solid-angle density of sky direction dir (unit), selection probability not included.
TRACER_HD float sky_direction_pdf(const SceneView& scene, Vec3 dir) {
  const uint32_t n = scene.sky_cells_per_side;
  if (n == 0) return 0.0f;
  float u, v;
  const uint32_t face = cube_face(dir, u, v);
  const uint32_t cx = min_of(trunc_to_uint32(u * static_cast<float>(n)), n - 1u);
  const uint32_t cy = min_of(trunc_to_uint32(v * static_cast<float>(n)), n - 1u);
  const uint32_t cell = (face * n + cy) * n + cx;
  const float pmf = scene.sky_cells[cell].pmf;
  const float a = 2.0f * u - 1.0f, b = 2.0f * v - 1.0f;
  const float r2 = 1.0f + a * a + b * b;
  return pmf * static_cast<float>(n * n) * 0.25f * r2 * det_sqrt(r2);
}

// A direction towards the sky drawn by cell_u (the cell) and (u1, u2) (the point in it).
TRACER_HD Vec3 sample_sky_direction(const SceneView& scene, float cell_u, float u1, float u2) {
  const uint32_t n = scene.sky_cells_per_side;
  const uint32_t cell = find_cdf_interval(scene.sky_cells, 6u * n * n, cell_u);
  const uint32_t face = cell / (n * n), cy = (cell / n) % n, cx = cell % n;
  const float a = 2.0f * (static_cast<float>(cx) + u1) / static_cast<float>(n) - 1.0f;
  const float b = 2.0f * (static_cast<float>(cy) + u2) / static_cast<float>(n) - 1.0f;
  return normalize(cube_direction(face, a, b));
}

}  // namespace tracer
