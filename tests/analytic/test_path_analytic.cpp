// The path integrator against closed-form answers. Where the estimator has no variance
// (every path's value is fixed) the tolerance is float rounding; where it has, the
// tolerance is five standard errors of the mean, estimated from the pixels themselves
// (independent: each pixel draws its own Philox numbers), so a correct renderer fails
// with probability below 1e-6.
#include <gtest/gtest.h>

#include <cmath>

#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

Image render(const std::string& json, const RenderOverrides& ov = {}) {
  RenderStats stats;
  Image image = render_cpu(test::scene_from(json, ov), 0, stats);
  EXPECT_EQ(stats.nonfinite_samples, 0u);
  return image;
}

using test::MeanStat;

constexpr double kFloatTolerance = 1e-6;  // a few ulps of values near 1, plus the film's 2^-32

std::string furnace(float albedo) {
  const std::string a = std::to_string(albedo);
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 4], "to": [0, 0, 0], "vfov": 35},
    "film": {"width": 48, "height": 48},
    "render": {"integrator": "path", "spp": 1, "sampler": "center", "max_depth": 16},
    "background": {"type": "constant", "radiance": [1, 1, 1]},
    "materials": {"m": {"type": "lambert", "albedo": [)" +
         a + "," + a + "," + a + R"(]}},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
}

// A convex Lambert object under a sky of radiance 1: every path that meets it scatters once
// and escapes, so it renders exactly its albedo; the sky around it renders 1.
TEST(PathAnalytic, FurnaceConvexObjectRendersItsAlbedo) {
  const Image img = render(furnace(0.6f));
  int covered = 0;
  for (size_t i = 0; i < img.rgb.size(); ++i) {
    const float v = img.rgb[i];
    const bool object = std::abs(v - 0.6f) <= kFloatTolerance;
    EXPECT_TRUE(object || v == 1.0f) << "value " << v << " at " << i / 3;
    covered += object;
  }
  EXPECT_GT(covered, 3 * 48 * 48 / 3);
}

TEST(PathAnalytic, FurnaceWithAlbedoOneIsUniform) {
  const Image img = render(furnace(1.0f));
  for (float v : img.rgb) ASSERT_NEAR(v, 1.0f, kFloatTolerance);
}

// The same furnace with the Sobol sampler in every dimension (film, each bounce): any
// sample of any path still returns exactly 1.
TEST(PathAnalytic, FurnaceWithAlbedoOneIsUniformWithTheSobolSampler) {
  RenderOverrides ov;
  ov.sampler = SamplerKind::Sobol;
  ov.spp = 4;
  const Image img = render(furnace(1.0f), ov);
  for (float v : img.rgb) ASSERT_NEAR(v, 1.0f, kFloatTolerance);
}

// A Lambert plane under a uniform sky reflects albedo times the sky's radiance.
TEST(PathAnalytic, PlaneUnderUniformSkyReflectsAlbedoTimesSky) {
  const Image img =
      render(R"({"format": "tracer-scene/1", "camera": {"from": [0, 2, 0], "to": [0, 0, 0.01], "vfov": 60},
    "film": {"width": 32, "height": 32}, "render": {"integrator": "path", "spp": 8, "sampler": "stochastic", "max_depth": 4},
    "background": {"type": "constant", "radiance": [2, 3, 4]},
    "materials": {"m": {"type": "lambert", "albedo": [0.7, 0.5, 0.25]}},
    "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"}]})");
  const float expected[3] = {1.4f, 1.5f, 1.0f};
  for (size_t i = 0; i < img.rgb.size(); ++i) ASSERT_NEAR(img.rgb[i], expected[i % 3], kFloatTolerance) << i;
}

// A Lambert plane under a cube-map sky that is dark but for its +y face of radiance L:
// the face is a square of half-side 1 at height 1 above every point, whose form factor
// is 4 (1/2pi) 2 (1/sqrt 2) atan(1/sqrt 2) (point to parallel rectangle, four corner
// pieces), so the plane reflects a L F with F = 0.5541264; with the sky sampled as a light
// and without (only BSDF rays find it).
void plane_under_bright_top_face(bool sky_sampling, SamplerKind sampler = SamplerKind::Stochastic) {
  const auto dir = test::temp_dir("sky-top-face");
  const std::string faces = test::write_cube_faces(dir, 4, [](int face, int, int) {
    return face == 2 ? Vec3{2.0f, 2.0f, 2.0f} : Vec3{0.0f, 0.0f, 0.0f};
  });
  RenderOverrides ov;
  ov.sky_sampling = sky_sampling ? Switch::On : Switch::Off;
  ov.sampler = sampler;
  RenderStats stats;
  const Image img = render_cpu(
      load_scene_text(R"({"format": "tracer-scene/1", "camera": {"from": [0, 2, 0], "to": [0, 0, 0.01], "vfov": 60},
    "film": {"width": 32, "height": 32}, "render": {"integrator": "path", "spp": 16, "sampler": "stochastic", "max_depth": 4},
    "background": {"type": "cubemap", "faces": [)" +
                          faces + R"(]},
    "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"}]})",
                      (dir / "s.json").string(), ov),
      0, stats);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(stats.nonfinite_samples, 0u);
  const MeanStat m = test::channel_mean(img, 0);
  EXPECT_NEAR(m.mean, 0.5 * 2.0 * 0.5541264, 5 * m.stderr_) << "stderr " << m.stderr_;
  EXPECT_GT(m.stderr_, 0.0) << "the estimator has variance here";
}

TEST(PathAnalytic, PlaneUnderABrightCubeFaceWithSkySampling) { plane_under_bright_top_face(true); }
TEST(PathAnalytic, PlaneUnderABrightCubeFaceWithoutSkySampling) { plane_under_bright_top_face(false); }
TEST(PathAnalytic, PlaneUnderABrightCubeFaceWithSkySamplingAndTheSobolSampler) {
  plane_under_bright_top_face(true, SamplerKind::Sobol);
}

// Inside a closed sphere of albedo a whose surface emits Le, every point sees
// Le + a Le + a^2 Le + ... = Le / (1 - a); with a = 0.5, Le = 0.5: 1.
void closed_emitting_sphere(bool nee, SamplerKind sampler = SamplerKind::Stochastic) {
  RenderOverrides ov;
  ov.nee = nee ? Switch::On : Switch::Off;
  ov.sampler = sampler;
  const Image img = render(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 0], "to": [0, 0, 1], "vfov": 70},
    "film": {"width": 40, "height": 40}, "render": {"integrator": "path", "spp": 16, "sampler": "stochastic", "max_depth": 64},
    "materials": {"shell": {"type": "emissive", "radiance": [0.5, 0.5, 0.5], "albedo": [0.5, 0.5, 0.5], "two_sided": true}},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "shell"}]})",
                           ov);
  for (int c = 0; c < 3; ++c) {
    const MeanStat m = test::channel_mean(img, c);
    EXPECT_NEAR(m.mean, 1.0, 5 * m.stderr_ + kFloatTolerance) << "channel " << c << ", stderr " << m.stderr_;
    EXPECT_GT(m.stderr_, 0.0) << "the estimator has variance here";
  }
}

TEST(PathAnalytic, InsideAnEmittingSphereWithNee) { closed_emitting_sphere(true); }
TEST(PathAnalytic, InsideAnEmittingSpherePlainEstimator) { closed_emitting_sphere(false); }
TEST(PathAnalytic, InsideAnEmittingSphereWithNeeAndTheSobolSampler) {
  closed_emitting_sphere(true, SamplerKind::Sobol);
}

// A point light of intensity I at the centre of a Lambert sphere of radius r and albedo a:
// irradiance I / r^2 everywhere, radiance a I / (pi r^2 (1 - a)) with interreflection.
// a = 0.5, I = pi, r = 2: 0.25.
TEST(PathAnalytic, PointLightAtTheCentreOfALambertSphere) {
  const Image img = render(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 0.5], "to": [0, 0, 1], "vfov": 70},
    "film": {"width": 40, "height": 40}, "render": {"integrator": "path", "spp": 16, "sampler": "stochastic", "max_depth": 64},
    "materials": {"shell": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "lights": [{"type": "point", "position": [0, 0, 0], "intensity": [3.14159265, 3.14159265, 3.14159265]}],
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 2, "material": "shell"}]})");
  const MeanStat m = test::channel_mean(img, 1);
  EXPECT_NEAR(m.mean, 0.25, 5 * m.stderr_ + kFloatTolerance) << "stderr " << m.stderr_;
}

// A diffuse floor and sphere lit by a quad lamp outside the view (a visible lamp edge
// would put most of the error in a few pixels): the scene of the convergence tests.
std::string lit_room(uint32_t size) {
  const std::string n = std::to_string(size);
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 1, 3], "to": [0, 0.4, 0], "vfov": 50},
    "film": {"width": )" +
         n + R"(, "height": )" + n + R"(}, "render": {"integrator": "path", "sampler": "stochastic", "max_depth": 4},
    "materials": {"white": {"type": "lambert", "albedo": [0.7, 0.7, 0.7]}, "red": {"type": "lambert", "albedo": [0.7, 0.2, 0.2]},
                  "lamp": {"type": "emissive", "radiance": [8, 8, 8]}},
    "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"},
               {"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "red"},
               {"type": "quad", "corner": [-0.5, 2, -0.5], "u": [1, 0, 0], "v": [0, 0, 1], "material": "lamp"}]})";
}

Image render_room(uint32_t size, uint32_t spp, uint64_t seed, bool nee) {
  RenderOverrides ov;
  ov.spp = spp;
  ov.seed = seed;
  ov.nee = nee ? Switch::On : Switch::Off;
  return render(lit_room(size), ov);
}

// Next-event estimation with MIS and the plain estimator have the same expectation: the
// per-pixel differences average to zero within five standard errors.
TEST(PathAnalytic, NeeAndPlainEstimatorConvergeToTheSameImage) {
  const Image with = render_room(24, 256, 1, true), without = render_room(24, 256, 2, false);
  Image diff = with;
  for (size_t i = 0; i < diff.rgb.size(); ++i) diff.rgb[i] = with.rgb[i] - without.rgb[i];
  for (int c = 0; c < 3; ++c) {
    const MeanStat d = test::channel_mean(diff, c), level = test::channel_mean(with, c);
    EXPECT_NEAR(d.mean, 0.0, 5 * d.stderr_) << "channel " << c << ", image mean " << level.mean;
    EXPECT_GT(level.mean, 0.05);
  }
}

// Monte Carlo error falls as 1/sqrt(spp): the least-squares slope of log RMSE against
// log spp (8 to 512 spp, against an independent 8192-spp reference) is -1/2 within 10 %.
TEST(PathAnalytic, ErrorFallsAsOneOverSqrtSpp) {
  const Image ref = render_room(32, 8192, 99, true);
  std::vector<double> xs, ys;
  for (uint32_t spp : {8u, 32u, 128u, 512u}) {
    const Image img = render_room(32, spp, 1, true);
    double se = 0;
    for (size_t i = 0; i < img.rgb.size(); ++i) se += (img.rgb[i] - ref.rgb[i]) * double(img.rgb[i] - ref.rgb[i]);
    xs.push_back(std::log(double(spp)));
    ys.push_back(0.5 * std::log(se / img.rgb.size()));
  }
  const double n = xs.size();
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < xs.size(); ++i) sx += xs[i], sy += ys[i], sxx += xs[i] * xs[i], sxy += xs[i] * ys[i];
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_NEAR(slope, -0.5, 0.05);
  RecordProperty("slope", std::to_string(slope));
}

// A plane facing +y seen straight down through a very narrow camera (every ray at normal
// incidence within 0.1 degrees) under a background `sky`, one bounce.
std::string plane_seen_head_on(const std::string& material, const std::string& sky) {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 5, 0], "to": [0, 0, 0], "up": [0, 0, -1], "vfov": 0.2},
    "film": {"width": 64, "height": 64},
    "render": {"integrator": "path", "spp": 16, "sampler": "stochastic", "max_depth": 1, "nee": false},
    "background": )" +
         sky + R"(, "materials": {"m": )" + material + R"(},
    "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"}]})";
}

// The modified Phong specular lobe ks (e + 2) / (2 pi) cos^e(alpha) (Lafortune and Willems
// 1994) is normalised so that at normal incidence, where alpha is the angle to the normal, it
// reflects exactly ks of a uniform sky: the integral of (e + 2) / (2 pi) cos^(e+1) over the
// hemisphere is 1. (With (e + 1) it would reflect (e + 1) / (e + 2): 0.955 at e = 20.)
TEST(PathAnalytic, PhongSpecularLobeReflectsAllOfAUniformSkyAtNormalIncidence) {
  const Image img =
      render(plane_seen_head_on(R"({"type": "phong", "diffuse": [0, 0, 0], "specular": [1, 1, 1], "shininess": 20})",
                                R"({"type": "constant", "radiance": [1, 1, 1]})"));
  const MeanStat m = test::channel_mean(img, 0);
  EXPECT_NEAR(m.mean, 1.0, 5.0 * m.stderr_ + 1e-4) << "stderr " << m.stderr_;
}

// Metal roughness r is the Phong exponent e = 2 / r^2 - 2 (docs/materials.md): r = 0.5 gives
// e = 6. Under a sky whose radiance is the direction's y, a plane facing +y seen head-on
// returns albedo times the lobe's mean cosine about the mirror direction, (e + 1) / (e + 2)
// = 7/8 (the lobe's density is (e + 1) / (2 pi) cos^e).
TEST(PathAnalytic, MetalRoughnessSetsTheLobesMeanCosine) {
  const Image img = render(plane_seen_head_on(R"({"type": "metal", "albedo": [1, 1, 1], "roughness": 0.5})",
                                              R"({"type": "gradient", "zenith": [1, 1, 1], "horizon": [0, 0, 0]})"));
  const MeanStat m = test::channel_mean(img, 0);
  EXPECT_NEAR(m.mean, 7.0 / 8.0, 5.0 * m.stderr_ + 1e-4) << "stderr " << m.stderr_;
}

}  // namespace
}  // namespace tracer
