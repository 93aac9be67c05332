// The environment: the radiance a ray sees when it leaves the scene (a constant, a gradient, a
// cube map or an equirectangular map, kernel/light/equirect_map.h), and, for either map with
// render.sky_sampling on in the path tracer, a light sampled by its cells. The host divides each
// cube face into n x n cells (at most the face's texels) and gives
// each cell a probability proportional to the largest luminance of the filtered sky over it
// (found on its grid of half-texel steps, where the bilinear filter has its extremes) times its
// solid angle (tracer/scene/environment_cells.cpp); the cumulative sums are multiples of 2^-24, so the
// probability of drawing a cell with a 24-bit uniform is exactly its pmf. A direction is uniform
// in its cell on the face (coordinates a, b in [-1, 1] at distance 1), whose solid-angle density
// is pmf / (4 / n^2) * (1 + a^2 + b^2)^(3/2) (dA cos / r^2 = dA / r^3).
#pragma once
#include "kernel/base/float_to_int.h"
#include "kernel/light/equirect_map.h"
#include "kernel/light/light_records.h"
#include "kernel/scene/scene_view.h"
#include "kernel/shading/sampling.h"

namespace tracer {

// Whether a background of this kind can be sampled as a light (it has cells to draw).
TRACER_HD constexpr bool samples_environment(BackgroundKind kind) {
  return kind == BackgroundKind::Cubemap || kind == BackgroundKind::Environment;
}

// The number of cells of a distribution of columns x rows cells on each cube face, or on the
// equirectangular map (as 64 bits: a bundle's counts are checked before they are trusted).
TRACER_HD constexpr uint64_t environment_cell_count(BackgroundKind kind, uint32_t columns, uint32_t rows) {
  return (kind == BackgroundKind::Cubemap ? 6ull : 1ull) * columns * rows;
}

// The cube-map face a direction leaves through and its (u, v) there. Each face is seen from
// the centre looking along its axis f with an up vector U (+y for the side faces; +z for +y
// and -z for -y, as a head tilted up or down from looking along -z): right R = f x U,
// u = (1 + d.R / d.f) / 2 to the right, v = (1 + d.U / d.f) / 2 upward.
TRACER_HD uint32_t cube_face(Vec3 d, float& u, float& v) {
  const float ax = abs_of(d.x), ay = abs_of(d.y), az = abs_of(d.z);
  uint32_t face;
  float right, up, along;
  if (ax >= ay && ax >= az) {
    face = d.x >= 0.0f ? 0u : 1u;
    along = ax;
    right = d.x >= 0.0f ? d.z : -d.z;
    up = d.y;
  } else if (ay >= az) {
    face = d.y >= 0.0f ? 2u : 3u;
    along = ay;
    right = d.x;
    up = d.y >= 0.0f ? d.z : -d.z;
  } else {
    face = d.z >= 0.0f ? 4u : 5u;
    along = az;
    right = d.z >= 0.0f ? -d.x : d.x;
    up = d.y;
  }
  u = 0.5f * (1.0f + right / along);
  v = 0.5f * (1.0f + up / along);
  return face;
}

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

TRACER_HD Vec3 background_radiance(const SceneView& scene, Vec3 dir) {
  const Background& bg = scene.background;
  switch (bg.kind) {
    case BackgroundKind::Gradient: {
      const float t = max_of(dir.y, 0.0f);  // horizon at y <= 0, zenith straight up
      return bg.horizon * (1.0f - t) + bg.radiance * t;
    }
    case BackgroundKind::Cubemap: {
      float u, v;
      const uint32_t face = cube_face(dir, u, v);
      return sample_texture(scene.textures, scene.texels, bg.faces[face], u, v);
    }
    case BackgroundKind::Environment: return equirect_radiance(scene, dir);
    case BackgroundKind::Constant: break;
  }
  return bg.radiance;
}

// Solid-angle density of environment direction dir (unit), selection probability not included.
TRACER_HD float environment_direction_pdf(const SceneView& scene, Vec3 dir) {
  if (scene.sky_cell_columns == 0) return 0.0f;
  if (scene.background.kind == BackgroundKind::Environment) return equirect_direction_pdf(scene, dir);
  const uint32_t n = scene.sky_cell_columns;
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

// A direction towards the environment drawn by cell_u (the cell) and (u1, u2) (the point in it).
TRACER_HD Vec3 sample_environment_direction(const SceneView& scene, float cell_u, float u1, float u2) {
  if (scene.background.kind == BackgroundKind::Environment) return sample_equirect_direction(scene, cell_u, u1, u2);
  const uint32_t n = scene.sky_cell_columns;
  const uint32_t cell = find_cdf_interval(scene.sky_cells, 6u * n * n, cell_u);
  const uint32_t face = cell / (n * n), cy = (cell / n) % n, cx = cell % n;
  const float a = 2.0f * (static_cast<float>(cx) + u1) / static_cast<float>(n) - 1.0f;
  const float b = 2.0f * (static_cast<float>(cy) + u2) / static_cast<float>(n) - 1.0f;
  return normalize(cube_direction(face, a, b));
}

// Solid-angle density with which next-event estimation draws environment direction dir
// (selection probability included); 0 when the environment is not sampled.
TRACER_HD float environment_light_pdf(const SceneView& scene, Vec3 dir) {
  if (scene.environment_light == kNoHit) return 0.0f;
  return scene.light_table[scene.environment_light].pmf * environment_direction_pdf(scene, dir);
}

// A sample of the environment by cell_u (the cell) and (u1, u2) (the direction in it).
TRACER_HD LightSample sample_environment_light(const SceneView& scene, float cell_u, float u1, float u2) {
  LightSample s = {
      {0.0f, 0.0f, 0.0f}, kInfinity, {0.0f, 0.0f, 0.0f}, 0.0f, LightKind::Environment, false, kNoHit, false};
  s.wi = sample_environment_direction(scene, cell_u, u1, u2);
  s.radiance = background_radiance(scene, s.wi);
  s.pdf = environment_light_pdf(scene, s.wi);
  s.valid = s.pdf > 0.0f && s.pdf < kInfinity;
  return s;
}

}  // namespace tracer
