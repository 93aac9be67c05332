// Roughness -> 0: a microfacet material's image converges to its smooth twin's.
//
// A sphere in front of an emissive checkerboard floor and a gradient sky (no lights, so no
// delta highlight that only one of the two can show) is path traced at roughness 0.3, 0.1,
// 0.03 and 0.012 (GGX alpha 0.09 down to 1.4e-4) and compared with the smooth material:
// the RMS difference falls with every step, and at 0.012 is a small part of what it is at
// 0.3 and of the noise (the smooth image against itself at another seed).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

const float kRoughness[] = {0.3f, 0.1f, 0.03f, 0.012f};

Image render_sphere(const std::string& material, int seed) {
  const Scene scene = test::scene_from(R"({"format": "tracer-scene/1",
    "camera": {"from": [0, 1.2, 4], "to": [0, -0.1, 0], "vfov": 34},
    "film": {"width": 32, "height": 32},
    "render": {"integrator": "path", "spp": 64, "sampler": "stochastic", "max_depth": 8, "rr_depth": 16, "seed": )" +
                                       std::to_string(seed) + R"(},
    "background": {"type": "gradient", "zenith": [0.3, 0.5, 1.0], "horizon": [1.0, 0.9, 0.7]},
    "materials": {"m": )" + material + R"(,
      "floor": {"type": "emissive", "radiance": {"checker": {"scale": 2, "even": [0.9, 0.9, 0.9], "odd": [0.05, 0.05, 0.05]}}}},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"},
               {"type": "quad", "corner": [-20, -1, 20], "u": [40, 0, 0], "v": [0, 0, -40], "material": "floor"}]})");
  RenderStats stats;
  return render_cpu(scene, 0, stats);
}

double rms_difference(const Image& a, const Image& b) {
  double sum = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i) sum += double(a.rgb[i] - b.rgb[i]) * (a.rgb[i] - b.rgb[i]);
  return std::sqrt(sum / a.rgb.size());
}

// `rough` is a material with "ROUGHNESS" where its roughness goes; `smooth` its smooth twin.
// Every image has the same seed, so the camera rays and the sampler's numbers are the same
// and what differs is the material alone; the smooth image at another seed gives the scale
// of the noise.
void expect_convergence(const std::string& rough, const std::string& smooth) {
  const Image reference = render_sphere(smooth, 1);
  const double noise = rms_difference(reference, render_sphere(smooth, 2));
  std::vector<double> error;
  for (float r : kRoughness) {
    std::string material = rough;
    material.replace(material.find("ROUGHNESS"), 9, std::to_string(r));
    error.push_back(rms_difference(render_sphere(material, 1), reference));
  }
  for (size_t i = 1; i < error.size(); ++i)
    EXPECT_LT(error[i], error[i - 1]) << "roughness " << kRoughness[i] << " against " << kRoughness[i - 1];
  // Measured: 1/55 (conductors) and 1/57 (glass); with alpha = roughness (not its square), 1/12 and 1/6.
  EXPECT_LT(error.back(), error.front() / 20) << "roughness 0.012 against 0.3";
  // Measured: 1/14 (conductors) and 1/12 (glass) of the noise; with alpha = roughness, 1.2-1.3 and 0.7.
  EXPECT_LT(error.back(), noise / 10) << "roughness 0.012 against smooth, and the smooth image at another seed";
}

TEST(MicrofacetConvergence, SchlickConductorToMirror) {
  expect_convergence(R"({"type": "conductor", "albedo": [0.95, 0.64, 0.54], "roughness": ROUGHNESS})",
                     R"({"type": "conductor", "albedo": [0.95, 0.64, 0.54], "roughness": 0})");
}

TEST(MicrofacetConvergence, ExactFresnelConductorToMirror) {
  const std::string gold = R"("eta": [0.143, 0.374, 1.442], "k": [3.983, 2.385, 1.603])";
  expect_convergence(R"({"type": "conductor", )" + gold + R"(, "roughness": ROUGHNESS})",
                     R"({"type": "conductor", )" + gold + R"(, "roughness": 0})");
}

// glTF's metal-rough never takes the smooth path (roughness is clamped to 0.01): fully
// metallic, it converges to the smooth Schlick conductor of its base colour.
TEST(MicrofacetConvergence, MetallicMetalRoughToMirror) {
  expect_convergence(R"({"type": "metal_rough", "base_color": [0.9, 0.9, 0.6], "metallic": 1, "roughness": ROUGHNESS})",
                     R"({"type": "conductor", "albedo": [0.9, 0.9, 0.6], "roughness": 0})");
}

TEST(MicrofacetConvergence, RoughDielectricToSmoothGlass) {
  expect_convergence(R"({"type": "rough_dielectric", "ior": 1.5, "roughness": ROUGHNESS})",
                     R"({"type": "dielectric", "ior": 1.5})");
}

}  // namespace
}  // namespace tracer
