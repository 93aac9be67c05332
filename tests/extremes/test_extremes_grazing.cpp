// Grazing incidence, cos theta from 1e-1 down to 1e-7: reflected and refracted directions
// stay unit and finite, both Fresnel models stay in [0, 1], and rays skimming spheres,
// planes and triangles hit or miss without NaN; a render looking along a glass-strewn floor
// counts no NaN/inf sample.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/geom/plane.h"
#include "kernel/geom/sphere.h"
#include "kernel/geom/triangle.h"
#include "kernel/shading/optics.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

constexpr float kCosines[] = {1e-1f, 1e-2f, 1e-3f, 1e-4f, 1e-5f, 1e-6f, 1e-7f};

Vec3 grazing_direction(float cos_i) {  // towards the surface of normal +y
  return normalize(Vec3{std::sqrt(1.0f - cos_i * cos_i), -cos_i, 0.0f});
}

TEST(ExtremesGrazing, DirectionsStayUnitAndFresnelInRange) {
  const Vec3 n = {0, 1, 0};
  for (const float c : kCosines) {
    const Vec3 d = grazing_direction(c);
    const Vec3 r = reflect(d, n);
    EXPECT_NEAR(length(r), 1.0f, 1e-6f) << c;
    EXPECT_GE(r.y, 0.0f) << c;
    for (const float eta : {1.0f / 1.5f, 1.0f / 4.0f, 1.0f / 1.000001f}) {
      Vec3 t;
      float cos_t = 0;
      ASSERT_TRUE(refract(d, n, eta, t, cos_t)) << c << " entering a denser medium never reflects totally";
      EXPECT_NEAR(length(t), 1.0f, 1e-6f) << c << " eta " << eta;
      EXPECT_TRUE(std::isfinite(cos_t) && cos_t >= 0.0f && cos_t <= 1.0f) << c;
      for (const FresnelKind model : {FresnelKind::Schlick, FresnelKind::Exact}) {
        const float f = dielectric_reflectance(model, -dot(d, n), cos_t, 1.0f, 1.0f / eta);
        EXPECT_TRUE(f >= 0.0f && f <= 1.0f) << c << " eta " << eta << " gives " << f;
      }
    }
    Vec3 t;
    float cos_t = 0;
    EXPECT_FALSE(refract(d, n, 1.5f, t, cos_t)) << c << ": leaving glass at grazing angles reflects totally";
  }
}

TEST(ExtremesGrazing, SkimmingRaysHitOrMissWithoutNaN) {
  for (const float c : kCosines) {
    const Vec3 d = grazing_direction(c);
    const Ray ray = {{-1.0f, 1.0f, 0.0f}, d};
    float t = 0;
    ASSERT_TRUE(intersect_plane({0, 0, 0}, {0, 1, 0}, ray, 0.0f, kInfinity, t)) << c;
    EXPECT_NEAR(t, 1.0f / c, 1e-3f / c) << c;  // height 1 over the plane, falling c per unit
    float b0, b1, b2;
    const Ray low = {{-1.0f, 1e-3f, 0.0f}, d};
    if (intersect_triangle({-10, 0, -10}, {10, 0, -10}, {0, 0, 1e6f}, low, make_ray_shear(d), 0.0f, kInfinity, t, b0,
                           b1, b2)) {
      EXPECT_TRUE(std::isfinite(t) && std::isfinite(b0) && std::isfinite(b1) && std::isfinite(b2)) << c;
    }
    // A ray passing the unit sphere at height 1 - c over its top.
    const Ray skim = {{-3.0f, 1.0f - c, 0.0f}, {1, 0, 0}};
    if (intersect_sphere({0, 0, 0}, 1.0f, skim, 0.0f, kInfinity, t)) {
      EXPECT_TRUE(std::isfinite(t) && t > 0.0f) << c;
    }
  }
}

TEST(ExtremesGrazing, RenderAlongAGlassStrewnFloorHasNoNaN) {
  for (const char* integrator : {"whitted", "path"}) {
    RenderStats stats;
    const Image img = render_cpu(test::scene_from(std::string(R"({"format": "tracer-scene/1",
      "camera": {"from": [0, 1e-4, 4], "to": [0, 1e-4, 0], "vfov": 30}, "film": {"width": 48, "height": 32},
      "render": {"integrator": ")") + integrator + R"(", "spp": 4, "sampler": "stochastic", "max_depth": 8},
      "background": {"type": "gradient", "zenith": [0.3, 0.5, 1], "horizon": [1, 1, 1]},
      "lights": [{"type": "point", "position": [2, 3, 2], "intensity": [20, 20, 20]}],
      "materials": {"glass": {"type": "dielectric", "ior": 1.5}, "floor": {"type": "metal", "albedo": [0.8, 0.8, 0.8], "roughness": 0},
                    "rough": {"type": "metal", "albedo": [0.8, 0.8, 0.8], "roughness": 1}},
      "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
                 {"type": "sphere", "center": [-0.5, 0.3, 0], "radius": 0.3, "material": "glass"},
                 {"type": "sphere", "center": [0.5, 0.3, 0], "radius": 0.3, "material": "rough"}]})"),
                                 0, stats);
    EXPECT_EQ(stats.nonfinite_samples + stats.overflow_samples, 0u) << integrator;
    for (float v : img.rgb) ASSERT_TRUE(std::isfinite(v)) << integrator;
  }
}

}  // namespace
}  // namespace tracer
