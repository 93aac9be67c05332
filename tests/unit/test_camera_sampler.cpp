// Camera rays and the four sub-pixel samplers.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "kernel/camera/sampler.h"
#include "scene/camera_setup.h"

using namespace tracer;

TEST(Camera, CentreOfFilmLooksAtTarget) {
  const Camera cam = make_camera({{0, 1, 3.5f}, {0, 1, 0}, {0, 1, 0}, 40.0f, 0.0f, 3.5f}, 100, 50);
  const Ray r = camera_ray(cam, 50.0f, 25.0f, 0.5f, 0.5f);
  EXPECT_NEAR(r.dir.x, 0.0f, 1e-6f);
  EXPECT_NEAR(r.dir.y, 0.0f, 1e-6f);
  EXPECT_NEAR(r.dir.z, -1.0f, 1e-6f);
  EXPECT_EQ(r.origin, (Vec3{0, 1, 3.5f}));
}

// The top edge of the film is vfov/2 above the axis; pixel (0,0) is the top-left corner.
TEST(Camera, VerticalFieldOfViewAndOrientation) {
  const Camera cam = make_camera({{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, 0.0f, 1.0f}, 200, 100);
  const Ray top = camera_ray(cam, 100.0f, 0.0f, 0.5f, 0.5f);
  EXPECT_NEAR(std::atan2(top.dir.y, -top.dir.z), 30.0 * M_PI / 180.0, 1e-6);
  const Ray left = camera_ray(cam, 0.0f, 50.0f, 0.5f, 0.5f);
  EXPECT_LT(left.dir.x, 0.0f);
  EXPECT_NEAR(-left.dir.x / -left.dir.z, 2.0 * std::tan(30.0 * M_PI / 180.0), 1e-6);
}

// Thin lens: every lens sample's ray through one film point meets the focus plane at the
// same point (the point in focus).
TEST(Camera, ThinLensRaysConvergeOnFocusPlane) {
  const float focus = 4.0f;
  const Camera cam = make_camera({{0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45.0f, 0.5f, focus}, 64, 64);
  const Ray pin =
      camera_ray(Camera{cam.origin, cam.focal_top_left, cam.pixel_dx, cam.pixel_dy, cam.lens_u, cam.lens_v, 0.0f},
                 10.0f, 20.0f, 0.0f, 0.0f);
  const Vec3 target = ray_at(pin, focus / -pin.dir.z);
  for (float lu : {0.1f, 0.5f, 0.9f})
    for (float lv : {0.0f, 0.3f, 0.8f}) {
      const Ray r = camera_ray(cam, 10.0f, 20.0f, lu, lv);
      EXPECT_LE(length(r.origin - cam.origin), 0.25f + 1e-6f);
      const Vec3 p = ray_at(r, (focus + r.origin.z) / -r.dir.z);
      EXPECT_NEAR(p.x, target.x, 1e-5f);
      EXPECT_NEAR(p.y, target.y, 1e-5f);
    }
}

TEST(Sampler, CenterIsPixelCentre) {
  float x, y;
  film_offset(SamplerKind::Center, 1, 0, 0, 0, x, y);
  EXPECT_EQ(x, 0.5f);
  EXPECT_EQ(y, 0.5f);
}

TEST(Sampler, GridIsRegular) {
  std::set<std::pair<float, float>> seen;
  for (uint32_t s = 0; s < 16; ++s) {
    float x, y;
    film_offset(SamplerKind::Grid, 4, 0, 0, s, x, y);
    EXPECT_EQ(x, (static_cast<float>(s % 4) + 0.5f) / 4.0f);
    EXPECT_EQ(y, (static_cast<float>(s / 4) + 0.5f) / 4.0f);
    seen.insert({x, y});
  }
  EXPECT_EQ(seen.size(), 16u);
}

TEST(Sampler, StratifiedHasOneSampleInEveryStratum) {
  for (uint32_t pixel = 0; pixel < 200; ++pixel)
    for (uint32_t s = 0; s < 9; ++s) {
      float x, y;
      film_offset(SamplerKind::Stratified, 3, 42, pixel, s, x, y);
      EXPECT_EQ(static_cast<uint32_t>(x * 3.0f), s % 3);
      EXPECT_EQ(static_cast<uint32_t>(y * 3.0f), s / 3);
    }
}

// Stochastic offsets are uniform: a chi-square test over a 4x4 histogram.
TEST(Sampler, StochasticIsUniform) {
  int bins[16] = {};
  const int n = 160000;
  for (int i = 0; i < n; ++i) {
    float x, y;
    film_offset(SamplerKind::Stochastic, 1, 7, static_cast<uint32_t>(i), 0, x, y);
    ASSERT_GE(x, 0.0f);
    ASSERT_LT(x, 1.0f);
    ++bins[static_cast<int>(x * 4) + 4 * static_cast<int>(y * 4)];
  }
  double chi2 = 0.0;
  for (int b : bins) chi2 += (b - n / 16.0) * (b - n / 16.0) / (n / 16.0);
  EXPECT_LT(chi2, 37.7);  // 15 degrees of freedom, p = 0.001
}
