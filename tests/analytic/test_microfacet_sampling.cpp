// Sampling of the microfacet materials (kernel/shading/microfacet_bsdf.h through bsdf.h):
// chi-square of the sampled directions against eval_bsdf's density on a grid like Mitsuba's
// (alpha 0.05 to 1, theta 15/30/80 degrees, a conductor, glass from outside and from inside
// with total internal reflection, glTF metal-rough with all three lobes), fed by the fixed
// stream and by the Sobol sampler's points; every sample's density and weight against
// eval_bsdf; and the energy of a conductor with F = 1, its single-scattering albedo
// E(mu, alpha) tabulated here by quadrature of the GGX formulas in double, against the
// sample weights and against a rendered white furnace.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include <cmath>
#include <vector>

#include "chi2.h"
#include "kernel/camera/camera.h"
#include "kernel/camera/sampler.h"
#include "kernel/material/bsdf.h"
#include "microfacet_material.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

// The grid's 96 tests together fail a correct sampler with probability 1e-2: each at the
// Sidak-corrected significance 1 - (1 - 1e-2)^(1/96), as Mitsuba's chi-square tests do.
const double kSignificance = 1 - std::pow(1 - 1e-2, 1.0 / 96);
constexpr int kSamples = 200000, kCosBins = 32, kPhiBins = 48, kSub = 24;

enum class Inputs { Stream, Sobol };

struct Case {
  Material m;
  bool front;
  double theta_degrees;
};

Material material(MaterialKind kind, double alpha) {
  return test::microfacet_material(kind, static_cast<float>(std::sqrt(alpha)));
}

Vec3 direction(double cos_theta, double phi) {
  const double s = std::sqrt(std::max(0.0, 1 - cos_theta * cos_theta));
  return {float(s * std::cos(phi)), float(s * std::sin(phi)), float(cos_theta)};
}

const Vec3 kN = {0, 0, 1};

// Uniforms of sample i: the fixed stream, or the Sobol points the path tracer gives a BSDF
// sample (lobe choice: bounce 0's pair 1, second half; direction: pair 2).
void uniforms(Inputs inputs, test::InputStream& s, int i, float& u0, float& u1, float& u2) {
  if (inputs == Inputs::Stream) {
    u0 = s.next(), u1 = s.next(), u2 = s.next();
    return;
  }
  float unused;
  sobol_uniform2(7u, 0u, uint32_t(i), kDimFirstFree + 1u, unused, u0);
  sobol_uniform2(7u, 0u, uint32_t(i), kDimFirstFree + 2u, u1, u2);
}

int bin_of(Vec3 d) {
  const int c = std::min(kCosBins - 1, std::max(0, int((d.z + 1) / 2 * kCosBins)));
  const double phi = std::atan2(double(d.y), double(d.x)) + M_PI;
  const int p = std::min(kPhiBins - 1, int(phi / (2 * M_PI) * kPhiBins));
  return c * kPhiBins + p;
}

// Expected counts: eval_bsdf's density integrated over each bin by a kSub x kSub midpoint rule.
std::vector<double> expected_counts(const Case& c, Vec3 wo) {
  std::vector<double> expected(kCosBins * kPhiBins, 0.0);
  const double dc = 2.0 / kCosBins / kSub, dp = 2 * M_PI / kPhiBins / kSub;
  for (int b = 0; b < kCosBins * kPhiBins; ++b) {
    const int ci = b / kPhiBins, pi = b % kPhiBins;
    double sum = 0;
    for (int i = 0; i < kSub; ++i)
      for (int j = 0; j < kSub; ++j) {
        const double cos_theta = -1 + (ci * kSub + i + 0.5) * dc, phi = -M_PI + (pi * kSub + j + 0.5) * dp;
        sum += eval_bsdf(c.m, wo, direction(cos_theta, phi), kN, c.front).pdf;
      }
    expected[b] = sum * dc * dp * kSamples;
  }
  return expected;
}

double chi2_p(const Case& c, Inputs inputs) {
  const Vec3 wo = direction(std::cos(c.theta_degrees * M_PI / 180), 0.4);
  std::vector<double> observed(kCosBins * kPhiBins, 0.0);
  test::InputStream stream{11};
  for (int i = 0; i < kSamples; ++i) {
    float u0, u1, u2;
    uniforms(inputs, stream, i, u0, u1, u2);
    BsdfSample s;
    if (sample_bsdf(c.m, wo, kN, c.front, u0, u1, u2, s)) observed[bin_of(s.wi)] += 1;
  }
  return test::chi2_p_value(observed, expected_counts(c, wo));
}

std::vector<Case> mitsuba_grid() {
  std::vector<Case> cases;
  for (double alpha : {0.05, 0.2, 0.5, 1.0})
    for (double theta : {15.0, 30.0, 80.0}) {
      cases.push_back({material(MaterialKind::GgxConductor, alpha), true, theta});
      cases.push_back({material(MaterialKind::GgxDielectric, alpha), true, theta});
      cases.push_back({material(MaterialKind::GgxDielectric, alpha), false, theta});  // 80: past the critical angle
      cases.push_back({material(MaterialKind::GltfMetalRough, alpha), true, theta});
    }
  return cases;
}

TEST(MicrofacetSampling, ChiSquareOnMitsubasGridWithBothSamplers) {
  double smallest = 1;
  std::string where;
  for (const Case& c : mitsuba_grid())
    for (Inputs inputs : {Inputs::Stream, Inputs::Sobol}) {
      const double p = chi2_p(c, inputs);
      const std::string name = "kind " + std::to_string(int(c.m.kind)) + " roughness " + std::to_string(c.m.roughness) +
                               " theta " + std::to_string(c.theta_degrees) + " front " + std::to_string(c.front) +
                               (inputs == Inputs::Sobol ? " (Sobol)" : " (stream)");
      EXPECT_GT(p, kSignificance) << name;
      if (p < smallest) smallest = p, where = name;
    }
  std::printf("smallest p-value of the grid %.3g at %s (significance %.3g)\n", smallest, where.c_str(), kSignificance);
}

TEST(MicrofacetSampling, ChiSquareRejectsADensityWithoutG1) {
  Case c = {material(MaterialKind::GgxConductor, 0.5), true, 80.0};
  const Vec3 wo = direction(std::cos(80 * M_PI / 180), 0.4);
  std::vector<double> observed(kCosBins * kPhiBins, 0.0), expected = expected_counts(c, wo);
  test::InputStream stream{11};
  for (int i = 0; i < kSamples; ++i) {  // uniform over the hemisphere instead of the lobe
    const double cos_theta = stream.next();
    const Vec3 d = direction(cos_theta, 2 * M_PI * stream.next());
    if (eval_bsdf(c.m, wo, d, kN, true).pdf > 0) observed[bin_of(d)] += 1;
  }
  EXPECT_LT(test::chi2_p_value(observed, expected), 1e-12);
}

// What sample_bsdf returns is what eval_bsdf says of the same direction: the density, and
// the weight f cos / pdf.
TEST(MicrofacetSampling, SampledDensityAndWeightMatchEval) {
  for (const Case& c : mitsuba_grid()) {
    const Vec3 wo = direction(std::cos(c.theta_degrees * M_PI / 180), 0.4);
    test::InputStream stream{5};
    for (int i = 0; i < 2000; ++i) {
      BsdfSample s;
      const float u0 = stream.next(), u1 = stream.next(), u2 = stream.next();
      if (!sample_bsdf(c.m, wo, kN, c.front, u0, u1, u2, s)) continue;
      const BsdfValue v = eval_bsdf(c.m, wo, s.wi, kN, c.front);
      ASSERT_GT(v.pdf, 0.0f) << "a sampled direction has density 0";
      EXPECT_NEAR(s.pdf, v.pdf, 2e-3 * v.pdf) << "kind " << int(c.m.kind) << " r " << c.m.roughness;
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(s.weight[k], v.f_cos[k] / v.pdf, 2e-3 * (1e-3 + s.weight[k])) << "kind " << int(c.m.kind);
    }
  }
}

// E(mu, alpha) = int D(h) G2(o, i) / (4 mu) di over the upper hemisphere: the albedo of a
// conductor with F = 1, from the GGX formulas written again here in double, integrated in
// polar coordinates about the mirror direction (theta = pi s^3), where the lobe is.
double ggx_albedo(double mu, double alpha) {
  const double a2 = alpha * alpha, so = std::sqrt(1 - mu * mu);
  auto lambda = [&](double z, double s2) { return (std::sqrt(1 + a2 * s2 / (z * z)) - 1) / 2; };
  const double o[3] = {so, 0, mu}, axis[3] = {-so, 0, mu};       // the mirror direction
  const double t[3] = {axis[2], 0, -axis[0]}, b[3] = {0, 1, 0};  // a frame around it
  double sum = 0;
  const int n_s = 2000, n_p = 720;
  for (int i = 0; i < n_s; ++i) {
    const double s = (i + 0.5) / n_s, theta = M_PI * s * s * s, dtheta = 3 * M_PI * s * s / n_s;
    for (int j = 0; j < n_p; ++j) {
      const double phi = 2 * M_PI * (j + 0.5) / n_p;
      const double x = std::sin(theta) * std::cos(phi), y = std::sin(theta) * std::sin(phi), z = std::cos(theta);
      double w[3], h[3];
      for (int k = 0; k < 3; ++k) w[k] = t[k] * x + b[k] * y + axis[k] * z;
      if (w[2] <= 0) continue;
      for (int k = 0; k < 3; ++k) h[k] = o[k] + w[k];
      const double len = std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
      for (double& v : h) v /= len;
      const double q = h[0] * h[0] + h[1] * h[1] + a2 * h[2] * h[2];
      const double g2 = 1 / (1 + lambda(mu, so * so) + lambda(w[2], w[0] * w[0] + w[1] * w[1]));
      sum += a2 / (M_PI * q * q) * g2 / (4 * mu) * std::sin(theta) * dtheta * 2 * M_PI / n_p;
    }
  }
  return sum;
}

Material white_conductor(float roughness) {
  Material m{};
  m.kind = MaterialKind::GgxConductor;
  m.fresnel = FresnelKind::Schlick;
  m.albedo = {1, 1, 1};  // F0 = 1: F = 1 at every angle
  m.roughness = roughness;
  return m;
}

TEST(MicrofacetSampling, WhiteConductorReturnsItsSingleScatteringAlbedo) {
  double worst = 0, lowest = 1;
  for (double alpha : {0.05, 0.25, 0.6, 1.0})
    for (double mu : {1.0, 0.7, 0.3, 0.1}) {
      const double e = ggx_albedo(mu, alpha);
      EXPECT_LE(e, 1.0 + 1e-4) << "alpha " << alpha << " mu " << mu;
      const Material m = white_conductor(float(std::sqrt(alpha)));
      const Vec3 wo = direction(mu, 0.0);
      test::InputStream stream{3};
      double sum = 0;
      const int n = 400000;
      for (int i = 0; i < n; ++i) {
        BsdfSample s;
        const float u0 = stream.next(), u1 = stream.next(), u2 = stream.next();
        if (sample_bsdf(m, wo, kN, true, u0, u1, u2, s)) sum += s.weight.x;
      }
      // each weight G2/G1 is in [0, 1]: the standard error is below 0.5 / sqrt(n)
      EXPECT_NEAR(sum / n, e, 5 * 0.5 / std::sqrt(double(n)) + 1e-3) << "alpha " << alpha << " mu " << mu;
      worst = std::max(worst, std::abs(sum / n - e));
      lowest = std::min(lowest, e);
    }
  std::printf("E(mu, alpha) from %.3f to 1; sampled against quadrature: largest difference %.2e\n", lowest, worst);
  // At normal incidence a normal tilted past 45 degrees reflects below the horizon: for GGX
  // P(tan^2 theta_m > 1) = alpha^2 / (1 + alpha^2); shadowing takes 2e-4 more at alpha 0.05.
  EXPECT_NEAR(ggx_albedo(1.0, 0.05), 1 / (1 + 0.05 * 0.05), 5e-4);
}

// glTF's metal-rough with a white base colour in a white furnace: at normal incidence its
// albedo (reflection plus thin-walled transmission) does not exceed 1 for any metallic or
// transmission, nor does the pure metal's at any angle. Appendix B's fresnel_mix is not
// energy-conserving away from the normal (the diffuse term weighs 1 - F at the half vector
// of each direction): a white dielectric at roughness 0.3 returns 1.006 at mu 0.5 and 1.084
// at mu 0.1 (docs/materials.md), so those are not asserted.
TEST(MicrofacetSampling, WhiteMetalRoughNeverReturnsMoreThanItReceives) {
  for (float metallic : {0.0f, 0.5f, 1.0f})
    for (float transmission : {0.0f, 0.7f})
      for (double mu : {1.0, 0.5, 0.1}) {
        if (mu < 1 && metallic < 1) continue;
        Material m = material(MaterialKind::GltfMetalRough, 0.3);
        m.albedo = {1, 1, 1}, m.metallic = metallic, m.transmission = transmission;
        const Vec3 wo = direction(mu, 0.0);
        test::InputStream stream{9};
        double sum = 0, sum2 = 0;
        const int n = 200000;
        for (int i = 0; i < n; ++i) {
          BsdfSample s;
          const float u0 = stream.next(), u1 = stream.next(), u2 = stream.next();
          if (!sample_bsdf(m, wo, kN, true, u0, u1, u2, s)) continue;
          sum += s.weight.x, sum2 += double(s.weight.x) * s.weight.x;
        }
        const double mean = sum / n, error = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
        EXPECT_LE(mean, 1.0 + 5 * error) << "metallic " << metallic << " transmission " << transmission << " mu " << mu;
      }
}

// A sphere of the white conductor under a white sky: each pixel's value is the mean of
// E(mu) over its area (a 16 x 16 grid of camera rays, the sky's 1 where they miss); the mean
// error over the pixels is 0 within noise, and no pixel is far above 1.
TEST(MicrofacetSampling, WhiteFurnaceImageOfAConductorSphereIsItsAlbedo) {
  const int size = 40, spp = 256;
  const Scene scene =
      test::scene_from(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 4], "to": [0, 0, 0], "vfov": 32},
    "film": {"width": 40, "height": 40},
    "render": {"integrator": "path", "spp": 256, "sampler": "stochastic", "max_depth": 4, "rr_depth": 16},
    "background": {"type": "constant", "radiance": [1, 1, 1]},
    "materials": {"m": {"type": "conductor", "albedo": [1, 1, 1], "roughness": 0.8}},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})");
  RenderStats stats;
  const Image img = render_cpu(scene, 0, stats);
  std::vector<double> table;  // E at mu = (k + 0.5) / 64, interpolated linearly
  for (int k = 0; k < 64; ++k) table.push_back(ggx_albedo((k + 0.5) / 64, 0.8 * 0.8));
  auto albedo_seen = [&](float fx, float fy) {
    const Ray r = camera_ray(scene.camera, fx, fy, 0, 0);
    const double b = dot(r.origin, r.dir), c = dot(r.origin, r.origin) - 1.0, disc = b * b - c;  // unit sphere at 0
    if (disc <= 0) return 1.0;
    const Vec3 p = r.origin + r.dir * float(-b - std::sqrt(disc));
    const double k = std::min(63.0, std::max(0.0, -dot(r.dir, p) / length(p) * 64 - 0.5));
    const int k0 = std::min(62, int(k));
    return table[k0] + (table[k0 + 1] - table[k0]) * (k - k0);
  };
  double error_sum = 0;
  int count = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      double expected = 0;
      for (int i = 0; i < 16; ++i)
        for (int j = 0; j < 16; ++j) expected += albedo_seen(x + (j + 0.5f) / 16, y + (i + 0.5f) / 16) / 256;
      const float v = img.rgb[3 * (y * size + x)];
      EXPECT_LE(v, expected + 0.2) << "(" << x << ", " << y << ")";
      if (expected == 1.0) continue;  // the sky
      error_sum += v - expected;
      ++count;
    }
  ASSERT_GT(count, 400);
  // each sample weighs G2 / G1 in [0, 1]: a pixel's standard error is below 0.5 / sqrt(spp)
  EXPECT_NEAR(error_sum / count, 0.0, 5 * 0.5 / std::sqrt(double(spp) * count) + 1e-3) << count << " pixels";
}

}  // namespace
}  // namespace tracer
