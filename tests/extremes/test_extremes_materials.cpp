// Materials at their limits. A glass sphere of IOR 1 with exact Fresnel vanishes (the image
// matches the scene without it); Schlick's approximation leaves a reflection there, which is
// measured. IOR 1 + 1e-6 and 4, roughness 0 and 1, albedo 0 and 1 render finite, and the
// limits that have a closed form meet it.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/camera/camera.h"
#include "kernel/shading/optics.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

// A checker floor under a constant sky of 1 (no lights: both integrators light it the same
// way everywhere, so nothing but the sphere can change a pixel), and optionally a glass
// sphere standing on it.
std::string glass_scene(const std::string& integrator, const std::string& glass) {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 1.2, 5], "to": [0, 0.8, 0], "vfov": 35},
    "film": {"width": 96, "height": 72},
    "render": {"integrator": ")" +
         integrator + R"(", "spp": 4, "sampler": "stochastic", "max_depth": 16, "rr_depth": 16},
    "background": {"type": "constant", "radiance": [1, 1, 1]}, "ambient": [1, 1, 1],
    "materials": {"floor": {"type": "lambert", "albedo": {"checker": {"scale": 4, "even": [0.8, 0.8, 0.8], "odd": [0.2, 0.3, 0.4]}}})" +
         (glass.empty() ? "" : R"(, "glass": )" + glass) + R"(},
    "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"})" +
         (glass.empty() ? "" : R"(, {"type": "sphere", "center": [0, 1, 0], "radius": 1, "material": "glass"})") + "]}";
}

Image render(const std::string& json) {
  RenderStats stats;
  Image img = render_cpu(test::scene_from(json), 0, stats);
  EXPECT_EQ(stats.nonfinite_samples + stats.overflow_samples, 0u);
  return img;
}

// With exact Fresnel and IOR 1 the interface reflects nothing and bends nothing: R = 0 and
// the refracted direction is the incident one, at every angle down to cos 2^-62 (below
// that cos^2 leaves the normal floats).
TEST(ExtremesMaterials, ExactFresnelAtIorOneReflectsNothingAtAnyAngle) {
  for (float c = 1.0f; c >= 0x1p-62f; c *= 0.5f) {
    const Vec3 n = {0, 1, 0}, d = {std::sqrt(1.0f - c * c), -c, 0.0f};
    Vec3 t;
    float cos_t = 0;
    ASSERT_TRUE(refract(d, n, 1.0f, t, cos_t)) << c;
    EXPECT_EQ(cos_t, -dot(d, n)) << c;
    EXPECT_TRUE(t.x == d.x && t.y == d.y && t.z == d.z) << c;
    EXPECT_EQ(fresnel_exact(-dot(d, n), cos_t, 1.0f, 1.0f), 0.0f) << c;
  }
}

// The glass scene with an IOR-1 sphere of `fresnel` against the floor alone.
test::PixelDifferences ior_one_against_the_floor(const std::string& integrator, const std::string& fresnel) {
  const Image without = render(glass_scene(integrator, ""));
  const Image with =
      render(glass_scene(integrator, R"({"type": "dielectric", "ior": 1, "fresnel": ")" + fresnel + R"("})"));
  const test::PixelDifferences d = test::pixel_differences(with, without);
  std::printf("%s, IOR 1, %s Fresnel: max difference %.3g, mean %.3g, %zu pixels over 1e-3\n", integrator.c_str(),
              fresnel.c_str(), d.max(), d.mean(), d.count_over(1e-3));
  return d;
}

TEST(ExtremesMaterials, GlassOfIorOneVanishesWithExactFresnel) {
  for (const char* integrator : {"path", "whitted"}) {
    const test::PixelDifferences d = ior_one_against_the_floor(integrator, "exact");
    EXPECT_EQ(d.count_over(1e-3), 0u) << integrator;
    EXPECT_LE(d.mean(), 1e-6) << integrator;
  }
}

// Schlick's R0 + (1 - R0)(1 - cos)^5 is 0 at normal incidence but not at grazing, even
// with R0 = 0: a ring of reflection stays at the silhouette.
TEST(ExtremesMaterials, SchlickLeavesAReflectionAtIorOne) {
  EXPECT_EQ(fresnel_schlick(1.0f, 1.0f, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(fresnel_schlick(0.5f, 1.0f, 1.0f), 1.0f / 32.0f);
  EXPECT_EQ(fresnel_schlick(0.0f, 1.0f, 1.0f), 1.0f);
  for (const char* integrator : {"path", "whitted"})
    EXPECT_GT(ior_one_against_the_floor(integrator, "schlick").count_over(1e-3), 20u) << integrator;
}

// One sphere of `material` under a sky of `sky`, seen whole by a pinhole camera; with
// `aim` the camera looks at that point instead of the centre.
std::string sphere_scene(const std::string& integrator, const std::string& material, uint32_t size, uint32_t spp,
                         const std::string& sampler = "stochastic", const std::string& aim = "[0, 0, 0]",
                         const std::string& sky = "1") {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 4], "to": )" + aim + R"(, "vfov": 36},
    "film": {"width": )" +
         std::to_string(size) + R"(, "height": )" + std::to_string(size) + R"(},
    "render": {"integrator": ")" +
         integrator + R"(", "spp": )" + std::to_string(spp) + R"(, "sampler": ")" + sampler +
         R"(", "max_depth": 64, "rr_depth": 64},
    "background": {"type": "constant", "radiance": [)" +
         sky + ", " + sky + ", " + sky + R"(]},
    "materials": {"m": )" +
         material + R"(},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
}

// The white furnace: under a sky of 1, a sphere that scatters all it receives (a mirror,
// clear glass of any IOR, either Fresnel model; Lambert of albedo 1 is
// PathAnalytic.FurnaceWithAlbedoOneIsUniform) is invisible, every pixel 1. A convex body
// sends every scattered ray back to the sky, so each sample is exactly 1 in the path
// tracer; Whitted loses the weight left at max_depth.
TEST(ExtremesMaterials, WhiteFurnaceAtAlbedoOneAndAnyIor) {
  const std::vector<std::pair<std::string, std::string>> materials = {
      {"metal roughness 0", R"({"type": "metal", "albedo": [1, 1, 1], "roughness": 0})"},
      {"glass IOR 1 + 1e-6", R"({"type": "dielectric", "ior": 1.000001})"},
      {"glass IOR 1 + 1e-6 exact", R"({"type": "dielectric", "ior": 1.000001, "fresnel": "exact"})"},
      {"glass IOR 1.5", R"({"type": "dielectric", "ior": 1.5})"},
      {"glass IOR 4", R"({"type": "dielectric", "ior": 4})"},
      {"glass IOR 4 exact", R"({"type": "dielectric", "ior": 4, "fresnel": "exact"})"}};
  for (const auto& [name, material] : materials) {
    for (const char* integrator : {"path", "whitted"}) {
      const Image img = render(sphere_scene(integrator, material, 32, 4));
      double worst = 0;
      for (float v : img.rgb) worst = std::max(worst, std::abs(double(v) - 1.0));
      std::printf("%s, %s: largest |pixel - 1| %.3g\n", name.c_str(), integrator, worst);
      EXPECT_LE(worst, std::string(integrator) == "path" ? 0.0 : 1e-4) << name << ", " << integrator;
    }
  }
}

// Albedo 0 absorbs everything: the sphere's pixels are exactly 0, the sky's exactly 1.
TEST(ExtremesMaterials, AlbedoZeroIsBlack) {
  for (const char* material :
       {R"({"type": "lambert", "albedo": [0, 0, 0]})", R"({"type": "metal", "albedo": [0, 0, 0], "roughness": 0})",
        R"({"type": "metal", "albedo": [0, 0, 0], "roughness": 1})"}) {
    for (const char* integrator : {"path", "whitted"}) {
      const Image img = render(sphere_scene(integrator, material, 32, 1, "center"));
      int black = 0, sky = 0;
      for (float v : img.rgb) black += v == 0.0f, sky += v == 1.0f;
      EXPECT_GT(black, 300) << material << ", " << integrator;
      EXPECT_EQ(black + sky, int(img.rgb.size())) << material << ", " << integrator;
    }
  }
}

// Metal of roughness 1 samples its lobe uniformly over the hemisphere about the mirror
// direction (e = 2/r^2 - 2 = 0) and absorbs the part below the surface: two hemispheres
// whose poles are theta apart share a lune of angle pi - theta, so under a sky of 1 the
// expected value is 1 - theta/pi at incidence angle theta.
double rough_metal_expected(const Scene& scene, float fx, float fy) {
  const Ray r = camera_ray(scene.camera, fx, fy, 0.0f, 0.0f);
  const double t = test::ray_sphere_distance(r, 0, 0, 0, 1);
  if (t < 0) return 1.0;  // the sky
  const double nx = r.origin.x + t * r.dir.x, ny = r.origin.y + t * r.dir.y, nz = r.origin.z + t * r.dir.z;
  const double cos_theta = -(nx * r.dir.x + ny * r.dir.y + nz * r.dir.z);
  return 1.0 - std::acos(std::min(1.0, cos_theta)) / 3.14159265358979323846;
}

// The grid sampler's 16 x 16 film positions per pixel, each a Bernoulli trial of its own p.
TEST(ExtremesMaterials, RoughMetalKeepsTheLobeAboveTheSurface) {
  const uint32_t n = 16, size = 32;
  const Scene scene = test::scene_from(
      sphere_scene("path", R"({"type": "metal", "albedo": [1, 1, 1], "roughness": 1})", size, n * n, "grid"));
  RenderStats stats;
  const Image img = render_cpu(scene, 0, stats);
  double worst_z = 0, sum_error = 0, sum_variance = 0;  // per pixel, and over the whole sphere
  int on_sphere = 0;
  for (uint32_t y = 0; y < size; ++y) {
    for (uint32_t x = 0; x < size; ++x) {
      double mean = 0, variance = 0;
      for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
          const double p = rough_metal_expected(scene, x + (i + 0.5f) / n, y + (j + 0.5f) / n);
          mean += p / (n * n);
          variance += p * (1 - p) / double(n * n) / double(n * n);
        }
      const double v = img.rgb[3 * (y * size + x)];
      if (variance == 0) {
        EXPECT_EQ(v, mean) << x << ", " << y;
        continue;
      }
      ++on_sphere;
      worst_z = std::max(worst_z, std::abs(v - mean) / std::sqrt(variance));
      sum_error += v - mean;
      sum_variance += variance;
    }
  }
  const double total_z = sum_error / std::sqrt(sum_variance);
  std::printf("roughness 1: %d pixels on the sphere, largest |z| %.2f, z of their sum %.2f\n", on_sphere, worst_z,
              total_z);
  EXPECT_GT(on_sphere, 300);
  EXPECT_LT(worst_z, 5.0);
  EXPECT_LT(std::abs(total_z), 5.0);
}

// Very high spp: 2^22 samples of one pixel meet the closed form to its 5 standard errors
// (2.4e-4), and the film's fixed-point sum holds them all.
TEST(ExtremesMaterials, VeryHighSppMeetsTheClosedForm) {
  const uint32_t spp = 1u << 22;
  const Scene scene = test::scene_from(sphere_scene("path", R"({"type": "metal", "albedo": [1, 1, 1], "roughness": 1})",
                                                    1, spp, "stochastic", "[0.8, 0.3, 0]"));
  RenderStats stats;
  const Image img = render_cpu(scene, 0, stats);
  EXPECT_EQ(stats.nonfinite_samples + stats.overflow_samples, 0u);
  // Every film position of the pixel sees the sphere; the expectation averages over them.
  double p = 0;
  const int n = 64;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) p += rough_metal_expected(scene, (i + 0.5f) / n, (j + 0.5f) / n);
  p /= n * n;
  const double se = std::sqrt(p * (1 - p) / spp);
  std::printf("2^22 spp: %.6f, expected %.6f (s.e. %.2g)\n", img.rgb[0], p, se);
  EXPECT_LT(p, 0.95);
  EXPECT_NEAR(img.rgb[0], p, 5 * se);
}

}  // namespace
}  // namespace tracer
