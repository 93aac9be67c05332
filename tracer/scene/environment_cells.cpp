#include "scene/environment_cells.h"

#include <algorithm>
#include <cmath>

#include "kernel/light/environment_light.h"
#include "kernel/material/bsdf.h"

namespace tracer {
namespace {

constexpr uint32_t kMaxSkyCellsPerSide = 128;       // a cube face's cells along a side
constexpr uint32_t kMaxEquirectCellColumns = 1024;  // an equirectangular map's, around
constexpr uint32_t kMaxEquirectCellRows = 512;      // and from pole to pole

// The grid on which the bilinear filter's largest value over a cell lies: the filter is
// bilinear between texel centres, so for k texels per cell side the extremes are on the
// (2k + 1) points of half-texel steps.
uint32_t half_texel_steps(uint32_t texels, uint32_t cells) { return 2u * ((texels + cells - 1) / cells); }

// Each cell's weight from its luminance and solid angle; cdf rounded to multiples of 2^-24, the
// step of our uniforms, so the probability of drawing a cell is exactly cdf - previous cdf.
double set_cells(Scene& scene, const std::vector<double>& weight) {
  double total = 0.0;
  for (double w : weight) total += w;
  scene.sky_cells.assign(weight.size(), SkyCell{0.0f, 0.0f});
  if (!(total > 0.0)) return 0.0;
  double running = 0.0;
  float previous = 0.0f;
  for (size_t i = 0; i < weight.size(); ++i) {
    running += weight[i];
    const float cdf =
        i + 1 == weight.size() ? 1.0f : static_cast<float>(std::round(running / total * 0x1p24) * 0x1p-24);
    scene.sky_cells[i] = {cdf - previous, cdf};
    previous = cdf;
  }
  return total;
}

std::vector<double> cube_weights(const Scene& scene, uint32_t n) {
  const SceneView view = scene.view();
  const uint32_t steps = half_texel_steps(scene.textures[scene.background.faces[0]].width, n);
  std::vector<double> weight(6u * n * n);
  for (uint32_t face = 0; face < 6; ++face)
    for (uint32_t cy = 0; cy < n; ++cy)
      for (uint32_t cx = 0; cx < n; ++cx) {
        float brightest = 0.0f;
        for (uint32_t j = 0; j <= steps; ++j)
          for (uint32_t i = 0; i <= steps; ++i) {
            const float fx = static_cast<float>(i) / static_cast<float>(steps),
                        fy = static_cast<float>(j) / static_cast<float>(steps);
            const float a = 2.0f * (static_cast<float>(cx) + fx) / static_cast<float>(n) - 1.0f;
            const float b = 2.0f * (static_cast<float>(cy) + fy) / static_cast<float>(n) - 1.0f;
            brightest =
                std::max(brightest, luminance(background_radiance(view, normalize(cube_direction(face, a, b)))));
          }
        // dw = dA / r^3 on the face at distance 1, at the cell's centre
        const double a = 2.0 * (cx + 0.5) / n - 1.0, b = 2.0 * (cy + 0.5) / n - 1.0;
        weight[(face * n + cy) * n + cx] =
            brightest * 4.0 / (static_cast<double>(n) * n) / std::pow(1.0 + a * a + b * b, 1.5);
      }
  return weight;
}

// The map's filtered luminance is read in (u, v) directly: a cell is a rectangle there.
std::vector<double> equirect_weights(const Scene& scene, uint32_t columns, uint32_t rows) {
  const Background& bg = scene.background;
  const Texture& map = scene.textures[bg.map];
  const uint32_t steps_u = half_texel_steps(map.width, columns), steps_t = half_texel_steps(map.height, rows);
  std::vector<double> weight(size_t{columns} * rows);
  for (uint32_t cy = 0; cy < rows; ++cy) {
    const double band = std::cos(M_PI * cy / rows) - std::cos(M_PI * (cy + 1) / rows);
    for (uint32_t cx = 0; cx < columns; ++cx) {
      float brightest = 0.0f;
      for (uint32_t j = 0; j <= steps_t; ++j)
        for (uint32_t i = 0; i <= steps_u; ++i) {
          const float u = (static_cast<float>(cx) + static_cast<float>(i) / static_cast<float>(steps_u)) /
                          static_cast<float>(columns);
          const float t =
              (static_cast<float>(cy) + static_cast<float>(j) / static_cast<float>(steps_t)) / static_cast<float>(rows);
          brightest = std::max(
              brightest,
              luminance(sample_texture(scene.textures.data(), scene.texels.data(), bg.map, u, 1.0f - t) * bg.radiance));
        }
      weight[size_t{cy} * columns + cx] = brightest * (2.0 * M_PI / columns) * band;
    }
  }
  return weight;
}

}  // namespace

double build_environment_cells(Scene& scene) {
  const Background& bg = scene.background;
  std::vector<double> weight;
  if (bg.kind == BackgroundKind::Cubemap) {
    const uint32_t n = std::min(scene.textures[bg.faces[0]].width, kMaxSkyCellsPerSide);
    scene.sky_cell_columns = scene.sky_cell_rows = n;
    weight = cube_weights(scene, n);
  } else {
    const Texture& map = scene.textures[bg.map];
    scene.sky_cell_columns = std::min(map.width, kMaxEquirectCellColumns);
    scene.sky_cell_rows = std::min(map.height, kMaxEquirectCellRows);
    weight = equirect_weights(scene, scene.sky_cell_columns, scene.sky_cell_rows);
  }
  const double integral = set_cells(scene, weight);
  if (integral > 0.0) return integral;
  scene.sky_cells.clear();
  scene.sky_cell_columns = scene.sky_cell_rows = 0;
  return 0.0;
}

}  // namespace tracer
