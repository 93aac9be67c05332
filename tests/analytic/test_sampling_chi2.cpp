// Chi-square goodness-of-fit tests of every sampling routine of the path integrator: N
// samples are binned, each bin's expected count comes from the routine's density integrated
// in closed form over the bin, bins expecting fewer than 5 samples are pooled, and the test
// fails when the p-value of the chi-square statistic is below a significance of 1e-3. The
// inputs are a fixed stream, so a result is repeatable. The light samplers' densities are
// also checked against the light's solid angle: E[1 / pdf] over their samples. The cube-map
// sky's sampling: test_sampling_chi2_sky.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "chi2.h"
#include "kernel/camera/sampler.h"
#include "kernel/light/light.h"
#include "kernel/material/bsdf.h"
#include "light_fixture.h"
#include "test_util.h"

namespace tracer {
namespace {

constexpr double kSignificance = 1e-3;
constexpr int kSamples = 400000;

using Stream = test::InputStream;
using test::chi2_p_value;
using test::gamma_q;
using test::LightFixture;
using test::MeanEstimate;
using test::triangle_solid_angle;

// Where a sampling routine's uniforms come from: the fixed stream, or one pixel's points of
// the Sobol sampler in the pairs the path tracer gives a BSDF sample (the lobe choice is
// the second half of bounce 0's pair 1, the direction its pair 2; path.h).
enum class Inputs { Stream, Sobol };

// Directions binned by (cos theta, phi) about `axis`; `cdf_cos(c)` is the probability that
// cos theta < c. Returns the p-value.
template <class Sample, class CdfCos>
double direction_test(Vec3 axis, Sample sample, CdfCos cdf_cos, double cos_lo, Inputs inputs = Inputs::Stream,
                      int cos_bins = 16, int phi_bins = 24) {
  const Frame f = frame_around(axis);
  std::vector<double> observed(cos_bins * phi_bins, 0.0), expected(cos_bins * phi_bins, 0.0);
  Stream s{42};
  for (int i = 0; i < kSamples; ++i) {
    float u1, u2, u3, unused;
    if (inputs == Inputs::Sobol) {
      sobol_uniform2(42u, 0u, static_cast<uint32_t>(i), kDimFirstFree + 1u, unused, u1);
      sobol_uniform2(42u, 0u, static_cast<uint32_t>(i), kDimFirstFree + 2u, u2, u3);
    } else {
      u1 = s.next(), u2 = s.next(), u3 = s.next();
    }
    const Vec3 d = sample(u1, u2, u3);
    const double c = dot(d, f.n), phi = std::atan2(dot(d, f.b), dot(d, f.t)) + M_PI;
    const int ci = std::min(cos_bins - 1, std::max(0, int((c - cos_lo) / (1 - cos_lo) * cos_bins)));
    const int pi = std::min(phi_bins - 1, int(phi / (2 * M_PI) * phi_bins));
    observed[ci * phi_bins + pi] += 1;
  }
  for (int ci = 0; ci < cos_bins; ++ci) {
    const double c0 = cos_lo + (1 - cos_lo) * ci / cos_bins, c1 = cos_lo + (1 - cos_lo) * (ci + 1) / cos_bins;
    for (int pi = 0; pi < phi_bins; ++pi)
      expected[ci * phi_bins + pi] = kSamples * (cdf_cos(c1) - cdf_cos(c0)) / phi_bins;
  }
  return chi2_p_value(observed, expected);
}

Material material(MaterialKind kind) {
  Material m{};
  m.kind = kind;
  m.albedo = {0.8f, 0.8f, 0.8f};
  m.ior = 1.5f;
  m.tint = {1, 1, 1};
  return m;
}

double cosine_hemisphere_p(Inputs inputs) {
  const Vec3 n = normalize(Vec3{0.3f, 0.5f, -0.8f});
  const Material m = material(MaterialKind::Lambert);
  return direction_test(
      n,
      [&](float a, float b, float c) {
        BsdfSample s;
        EXPECT_TRUE(sample_bsdf(m, n, n, true, a, b, c, s));
        EXPECT_NEAR(s.pdf, dot(s.wi, n) / kPi, 1e-5);
        return s.wi;
      },
      [](double c) { return c * c; }, 0.0, inputs);  // P(cos < c) = c^2 for density cos / pi
}

TEST(SamplingChi2, CosineHemisphere) { EXPECT_GT(cosine_hemisphere_p(Inputs::Stream), kSignificance); }

double metal_lobe_p(Inputs inputs) {
  Material m = material(MaterialKind::PhongMetal);
  m.roughness = 0.4f;
  const float e = metal_exponent(m.roughness);
  const Vec3 n = {0, 1, 0};
  return direction_test(
      n,
      [&](float a, float b, float c) {
        BsdfSample s;
        EXPECT_TRUE(sample_bsdf(m, n, n, true, a, b, c, s));
        EXPECT_NEAR(s.pdf, eval_bsdf(m, n, s.wi, n, true).pdf, 1e-4 * s.pdf);
        return s.wi;
      },
      [&](double c) { return std::pow(c, e + 1.0); }, 0.0, inputs);  // density (e+1)/(2 pi) cos^e
}

TEST(SamplingChi2, MetalLobeAtNormalIncidence) { EXPECT_GT(metal_lobe_p(Inputs::Stream), kSignificance); }

double phong_lobes_p(Inputs inputs) {
  Material m = material(MaterialKind::Phong);
  m.albedo = {0.3f, 0.3f, 0.3f};
  m.specular = {0.5f, 0.5f, 0.5f};
  m.shininess = 20.0f;
  const Vec3 n = {0, 0, 1};
  const double pd = PhongMaterial::diffuse_probability(m);
  return direction_test(
      n,
      [&](float a, float b, float c) {
        BsdfSample s;
        EXPECT_TRUE(sample_bsdf(m, n, n, true, a, b, c, s));
        return s.wi;
      },
      [&](double c) { return pd * c * c + (1 - pd) * std::pow(c, m.shininess + 1.0); }, 0.0, inputs);
}

TEST(SamplingChi2, PhongLobes) { EXPECT_GT(phong_lobes_p(Inputs::Stream), kSignificance); }

// The same three lobes fed the Sobol sampler's points: a warp that distorts their density
// fails here as it would with independent uniforms.
TEST(SamplingChi2, BsdfLobesFromTheSobolSamplersPoints) {
  EXPECT_GT(cosine_hemisphere_p(Inputs::Sobol), kSignificance);
  EXPECT_GT(metal_lobe_p(Inputs::Sobol), kSignificance);
  EXPECT_GT(phong_lobes_p(Inputs::Sobol), kSignificance);
}

TEST(SamplingChi2, DielectricChoosesReflectionWithFresnelProbability) {
  for (FresnelKind model : {FresnelKind::Schlick, FresnelKind::Exact}) {
    Material m = material(MaterialKind::Dielectric);
    m.fresnel = model;
    const Vec3 n = {0, 0, 1}, wo = normalize(Vec3{0.8f, 0, 0.3f});
    Vec3 refracted;
    float cos_t;
    ASSERT_TRUE(refract(-wo, n, 1.0f / 1.5f, refracted, cos_t));
    const double f = dielectric_reflectance(model, dot(wo, n), cos_t, 1.0f, 1.5f);
    Stream s{7};
    double reflected = 0;
    for (int i = 0; i < kSamples; ++i) {
      BsdfSample b;
      const float u1 = s.next(), u2 = s.next(), u3 = s.next();
      ASSERT_TRUE(sample_bsdf(m, wo, n, true, u1, u2, u3, b));
      reflected += dot(b.wi, n) > 0;
    }
    const double p = chi2_p_value({reflected, kSamples - reflected}, {kSamples * f, kSamples * (1 - f)});
    EXPECT_GT(p, kSignificance) << "F " << f << ", reflected " << reflected / kSamples;
  }
}

// E[1 / pdf] over light samples is the solid angle the light subtends.
MeanEstimate inverse_pdf_of_light(const LightFixture& fx, Vec3 from) {
  Stream s{9};
  MeanEstimate e;
  for (int i = 0; i < kSamples; ++i) {
    const float u1 = s.next(), u2 = s.next();
    const LightSample ls = sample_light(fx.view, 0, from, u1, u2, 0.0f);
    EXPECT_TRUE(ls.valid) << "u1 " << u1 << " u2 " << u2;
    e.add(1.0 / ls.pdf);
  }
  return e;
}

TEST(SamplingChi2, SphereLightIsUniformInItsCone) {
  const LightFixture fx(R"({"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "lamp"})");
  const Vec3 from = {0.4f, 1.2f, 2.0f};
  const double d2 = dot(from, from), cos_max = std::sqrt(1 - 0.25 / d2);
  const double p = direction_test(
      -from / std::sqrt(float(d2)),
      [&](float a, float b, float) { return sample_light(fx.view, 0, from, a, b, 0.0f).wi; },
      [&](double c) { return (c - cos_max) / (1 - cos_max); }, cos_max);
  EXPECT_GT(p, kSignificance);
  const MeanEstimate omega = inverse_pdf_of_light(fx, from);
  EXPECT_NEAR(omega.mean(), 2 * M_PI * (1 - cos_max), omega.tolerance());
}

// Directions on the cone's rim (u1 near 1) graze the sphere; rounding made the first of these
// miss it and the sample come back invalid (found when clang fed the chi-square test its
// inputs in the other order). Every rim direction gives a valid sample on the surface.
TEST(SamplingChi2, SphereLightRimSamplesAreValid) {
  const LightFixture fx(R"({"type": "sphere", "center": [0, 0, 0], "radius": 0.5, "material": "lamp"})");
  const Vec3 from = {0.4f, 1.2f, 2.0f};
  std::vector<std::pair<float, float>> inputs = {{0.99999922513961792f, 0.83403116464614868f}};
  for (int i = 0; i < 4096; ++i) inputs.push_back({1.0f - 0x1p-24f * float(1 + i % 16), (i + 0.5f) / 4096});
  for (const auto& [u1, u2] : inputs) {
    const LightSample ls = sample_light(fx.view, 0, from, u1, u2, 0.0f);
    ASSERT_TRUE(ls.valid) << "u1 " << u1 << " u2 " << u2;
    const Vec3 q = from + ls.wi * ls.distance;
    EXPECT_NEAR(length(q), 0.5f, 1e-5f) << "u1 " << u1 << " u2 " << u2;
  }
}

// Positions binned on the unit square of the shape's parameters; for a triangle the bins
// are those of (b1, b2) with b1 + b2 <= 1, cut in half along the diagonal. (Rectangles with
// render.light_sampling "solid-angle": test_light_solid_angle.cpp.)
TEST(SamplingChi2, QuadAndTriangleLightsAreUniformByArea) {
  for (const bool triangle : {false, true}) {
    const LightFixture fx(
        triangle ? R"({"type": "triangle", "vertices": [[-1, -1, 0], [1, -1, 0], [-1, 1, 0]], "material": "lamp"})"
                 : R"({"type": "quad", "corner": [-1, -1, 0], "u": [2, 0, 0], "v": [0, 2, 0], "material": "lamp"})");
    const Vec3 from = {0.3f, -0.2f, 1.5f};
    constexpr int kBins = 12;
    std::vector<double> observed(kBins * kBins, 0.0), expected(kBins * kBins, 0.0);
    Stream s{5};
    MeanEstimate inverse_pdf;
    for (int i = 0; i < kSamples; ++i) {
      const float u1 = s.next(), u2 = s.next();
      const LightSample ls = sample_light(fx.view, 0, from, u1, u2, 0.0f);
      ASSERT_TRUE(ls.valid);
      inverse_pdf.add(1.0 / ls.pdf);
      const Vec3 q = from + ls.wi * ls.distance;
      const int bx = std::min(kBins - 1, std::max(0, int((q.x + 1) / 2 * kBins)));
      const int by = std::min(kBins - 1, std::max(0, int((q.y + 1) / 2 * kBins)));
      observed[by * kBins + bx] += 1;
    }
    for (int by = 0; by < kBins; ++by)
      for (int bx = 0; bx < kBins; ++bx) {
        const double area = !triangle ? 1.0 : bx + by + 1 < kBins ? 1.0 : bx + by + 1 == kBins ? 0.5 : 0.0;
        expected[by * kBins + bx] = kSamples * area / (triangle ? kBins * kBins / 2.0 : kBins * kBins);
      }
    EXPECT_GT(chi2_p_value(observed, expected), kSignificance) << (triangle ? "triangle" : "quad");
    // Solid angle of the shape from `from` in closed form; the quad is two triangles.
    const double omega = triangle ? triangle_solid_angle(from, {-1, -1, 0}, {1, -1, 0}, {-1, 1, 0})
                                  : triangle_solid_angle(from, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}) +
                                        triangle_solid_angle(from, {-1, -1, 0}, {1, 1, 0}, {-1, 1, 0});
    EXPECT_NEAR(inverse_pdf.mean(), omega, inverse_pdf.tolerance()) << (triangle ? "triangle" : "quad");
  }
}

TEST(SamplingChi2, GammaQKnownValues) {
  EXPECT_NEAR(gamma_q(1.0, 2.0), std::exp(-2.0), 1e-12);  // Q(1, x) = e^-x
  EXPECT_NEAR(gamma_q(0.5, 1.0), std::erfc(1.0), 1e-10);  // Q(1/2, x) = erfc(sqrt(x))
  // Integer a: Q(n, x) = e^-x sum_{k<n} x^k / k!  (chi-square with 10 dof at 40).
  EXPECT_NEAR(gamma_q(5.0, 20.0), std::exp(-20.0) * (1 + 20 + 200 + 8000.0 / 6 + 160000.0 / 24), 1e-15);
}

// The test has power: uniform hemisphere samples are not cosine-distributed.
TEST(SamplingChi2, RejectsAWrongDensity) {
  const double p = direction_test(
      {0, 0, 1}, [](float a, float b, float) { return direction_from(a, b); }, [](double c) { return c * c; }, 0.0);
  EXPECT_LT(p, 1e-12);
  const double p_sobol = direction_test(
      {0, 0, 1}, [](float, float b, float c) { return direction_from(b, c); }, [](double c) { return c * c; }, 0.0,
      Inputs::Sobol);
  EXPECT_LT(p_sobol, 1e-12) << "and with the Sobol sampler's points";
}

}  // namespace
}  // namespace tracer
