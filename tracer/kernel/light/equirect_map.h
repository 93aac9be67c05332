// The environment background: an equirectangular (latitude-longitude) image, turned about +y.
// In the map's frame a unit direction m has longitude phi = atan2(m.z, m.x) + pi, so
// u = phi / 2 pi (the image's centre looks along +x, as Blender's world texture does through
// glTF's axes), and polar angle theta = atan2(|m.xz|, m.y) from +y, t = theta / pi (the
// texture's v = 1 - t: row 0 is the top, straight up). The bilinear filter repeats in u and
// clamps at the poles (TextureLoader::environment_map).
//
// Sampling (the path tracer's environment light, when render.sky_sampling is on): the host
// splits the map into columns x rows cells of equal longitude and latitude steps and gives each
// a probability proportional to the largest filtered luminance over it times its solid angle
// (tracer/scene/environment_cells.cpp). A direction is uniform in solid angle within its cell:
// longitude uniform, cos(theta) uniform between the row's bounds (Archimedes' hat-box theorem),
// so its density is pmf / ((2 pi / columns) (cos theta_top - cos theta_bottom)), finite at the
// poles, where a density in (u, v) divided by 2 pi^2 sin(theta) is not.
#pragma once
#include "kernel/base/detmath.h"
#include "kernel/base/float_to_int.h"
#include "kernel/scene/scene_view.h"
#include "kernel/shading/sampling.h"
#include "kernel/shading/texture.h"

namespace tracer {

// A scene direction in the map's frame: turned by the map's angle the other way about +y.
TRACER_HD Vec3 into_map_frame(const Background& bg, Vec3 d) {
  return {bg.cos_turn * d.x - bg.sin_turn * d.z, d.y, bg.sin_turn * d.x + bg.cos_turn * d.z};
}

// A map-frame direction in the scene: the map's turn, x' = x cos + z sin, z' = z cos - x sin.
TRACER_HD Vec3 out_of_map_frame(const Background& bg, Vec3 m) {
  return {bg.cos_turn * m.x + bg.sin_turn * m.z, m.y, bg.cos_turn * m.z - bg.sin_turn * m.x};
}

// (u, t) of a map-frame direction: u in [0, 1] around +y, t in [0, 1] from +y down.
TRACER_HD void equirect_coordinates(Vec3 m, float& u, float& t) {
  constexpr float kInvTwoPi = 0.159154943091895335768f, kInvPi = 0.318309886183790671538f;
  u = 0.5f + det_atan2(m.z, m.x) * kInvTwoPi;
  t = det_atan2(det_sqrt(m.x * m.x + m.z * m.z), m.y) * kInvPi;
}

// cos(theta) at the top edge of row `row` of `rows` (row == rows: the bottom edge of the last).
TRACER_HD float equirect_row_cos(uint32_t row, uint32_t rows) {
  return det_cos(kPi * (static_cast<float>(row) / static_cast<float>(rows)));
}

TRACER_HD Vec3 equirect_radiance(const SceneView& scene, Vec3 dir) {
  const Background& bg = scene.background;
  float u, t;
  equirect_coordinates(into_map_frame(bg, dir), u, t);
  return sample_texture(scene.textures, scene.texels, bg.map, u, 1.0f - t) * bg.radiance;
}

// Solid-angle density with which sample_equirect_direction draws unit dir.
TRACER_HD float equirect_direction_pdf(const SceneView& scene, Vec3 dir) {
  const uint32_t columns = scene.sky_cell_columns, rows = scene.sky_cell_rows;
  float u, t;
  equirect_coordinates(into_map_frame(scene.background, dir), u, t);
  const uint32_t cx = min_of(trunc_to_uint32(u * static_cast<float>(columns)), columns - 1u);
  const uint32_t cy = min_of(trunc_to_uint32(t * static_cast<float>(rows)), rows - 1u);
  const float band = equirect_row_cos(cy, rows) - equirect_row_cos(cy + 1u, rows);
  const float solid_angle = 2.0f * kPi / static_cast<float>(columns) * band;
  return solid_angle > 0.0f ? scene.sky_cells[cy * columns + cx].pmf / solid_angle : 0.0f;
}

// A unit direction drawn by cell_u (the cell) and (u1, u2) (longitude and cos(theta) in it).
TRACER_HD Vec3 sample_equirect_direction(const SceneView& scene, float cell_u, float u1, float u2) {
  const uint32_t columns = scene.sky_cell_columns, rows = scene.sky_cell_rows;
  const uint32_t cell = find_cdf_interval(scene.sky_cells, columns * rows, cell_u);
  const uint32_t cy = cell / columns, cx = cell % columns;
  const float top = equirect_row_cos(cy, rows), bottom = equirect_row_cos(cy + 1u, rows);
  const float cos_theta = top + (bottom - top) * u2;
  const float sin_theta = det_sqrt(max_of(0.0f, 1.0f - cos_theta * cos_theta));
  float s, c;
  det_sincos(2.0f * kPi * ((static_cast<float>(cx) + u1) / static_cast<float>(columns)), s, c);
  return out_of_map_frame(scene.background, {-sin_theta * c, cos_theta, -sin_theta * s});
}

}  // namespace tracer
