// Closed forms of the GGX distribution and the microfacet materials (kernel/shading/
// microfacet.h, microfacet_bsdf.h, optics.h), by quadrature in double over the kernel's float
// functions: D is normalised over projected area, the weak white furnace (Heitz 2014) holds
// for every alpha and angle, known values, the conductor Fresnel against complex arithmetic,
// reciprocity, and the rough dielectric's energy between reflection and transmission.
#include <gtest/gtest.h>

#include <cstdio>

#include <cmath>
#include <complex>
#include <functional>

#include "kernel/material/bsdf.h"
#include "microfacet_material.h"

namespace tracer {
namespace {

const double kAlphas[] = {0.01, 0.1, 0.5, 1.0};
const double kThetasDegrees[] = {0.0, 30.0, 60.0, 80.0, 89.0, 89.9};

Vec3 direction(double theta, double phi) {
  return {static_cast<float>(std::sin(theta) * std::cos(phi)), static_cast<float>(std::sin(theta) * std::sin(phi)),
          static_cast<float>(std::cos(theta))};
}

// The integral of g over the sphere of directions in the polar coordinates of `axis`
// (midpoint rule in s with theta = pi s^3, so a lobe as narrow as alpha 0.01 about the axis
// is resolved, and in phi).
double sphere_integral(Vec3 axis, const std::function<double(Vec3)>& g, int n_s = 3000, int n_phi = 360) {
  const Frame f = frame_around(axis);
  double sum = 0;
  for (int i = 0; i < n_s; ++i) {
    const double s = (i + 0.5) / n_s, theta = M_PI * s * s * s, dtheta = 3 * M_PI * s * s / n_s;
    double ring = 0;
    for (int j = 0; j < n_phi; ++j) ring += g(f.to_world(direction(theta, 2 * M_PI * (j + 0.5) / n_phi)));
    sum += ring * std::sin(theta) * dtheta * 2 * M_PI / n_phi;
  }
  return sum;
}

TEST(Microfacet, DistributionIntegratesToOneOverProjectedArea) {
  for (double alpha : kAlphas) {
    const double integral =
        sphere_integral({0, 0, 1}, [&](Vec3 m) { return ggx_d(m, float(alpha)) * std::max(0.0f, m.z); });
    EXPECT_NEAR(integral, 1.0, 1e-4) << "alpha " << alpha;
  }
}

// Heitz 2014, eq. 40: the projected area of the visible microfacets is that of the
// geometric surface, int G1(wo, m) D(m) max(0, wo.m) dm = cos(theta_o): D_wo integrates to 1.
TEST(Microfacet, WeakWhiteFurnaceHoldsForEveryAlphaAndAngle) {
  double worst = 0, worst_visible = 0;
  for (double alpha : kAlphas)
    for (double degrees : kThetasDegrees) {
      const Vec3 wo = direction(degrees * M_PI / 180, 0.3);
      const double integral = sphere_integral({0, 0, 1}, [&](Vec3 m) {
        return double(ggx_g1(wo, float(alpha))) * ggx_d(m, float(alpha)) * std::max(0.0f, dot(wo, m));
      });
      EXPECT_NEAR(integral / wo.z, 1.0, 2e-3) << "alpha " << alpha << ", theta " << degrees;
      const double visible =
          sphere_integral({0, 0, 1}, [&](Vec3 m) { return ggx_visible_normal_pdf(wo, m, float(alpha)); });
      EXPECT_NEAR(visible, 1.0, 2e-3) << "D_wo, alpha " << alpha << ", theta " << degrees;
      worst = std::max(worst, std::abs(integral / wo.z - 1.0));
      worst_visible = std::max(worst_visible, std::abs(visible - 1.0));
    }
  std::printf("largest |furnace / cos - 1| %.2e, |int D_wo - 1| %.2e (tolerance 2e-3)\n", worst, worst_visible);
}

TEST(Microfacet, KnownValues) {
  const double theta = 0.98 * M_PI / 2;
  EXPECT_NEAR(ggx_g1(direction(theta, 0), 0.1f), 0.46130955f, 3e-7);
  EXPECT_EQ(ggx_g1({0, 0, 1}, 0.5f), 1.0f);
  EXPECT_NEAR(ggx_d({0, 0, 1}, 0.1f), 1 / (M_PI * 0.01), 1e-6 / (M_PI * 0.01));
  EXPECT_EQ(ggx_alpha(0.5f), 0.25f) << "alpha = roughness^2";
  // Lambda against (sqrt(1 + alpha^2 tan^2) - 1) / 2 in double, normal to grazing.
  for (double alpha : kAlphas)
    for (double degrees = 0; degrees < 90; degrees += 0.25) {
      const Vec3 w = direction(degrees * M_PI / 180, 1.0);
      const double tan2 = (double(w.x) * w.x + double(w.y) * w.y) / (double(w.z) * w.z);
      const double lambda = (std::sqrt(1 + alpha * alpha * tan2) - 1) / 2;
      EXPECT_NEAR(ggx_lambda(w, float(alpha)), lambda, 2e-6 * (1 + lambda)) << alpha << " " << degrees;
    }
  EXPECT_EQ(ggx_g1({1, 0, 0}, 0.5f), 0.0f) << "grazing: shadowed";
}

// Born and Wolf's reflectance of a conductor, from the complex index by complex arithmetic.
double conductor_reflectance(double cos_i, std::complex<double> eta) {
  const double sin2 = 1 - cos_i * cos_i;
  const std::complex<double> cos_t = std::sqrt(1.0 - sin2 / (eta * eta));
  const std::complex<double> rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  const std::complex<double> rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  return (std::norm(rs) + std::norm(rp)) / 2;
}

TEST(Microfacet, ConductorFresnelMatchesComplexArithmetic) {
  const double metals[][2] = {{0.143, 3.983}, {0.374, 2.385}, {1.442, 1.603}, {2.5, 0.0}, {0.2, 8.0}};
  for (const auto& metal : metals)
    for (double c = 0.0; c <= 1.0; c += 1.0 / 64) {
      const double expected = conductor_reflectance(c, {metal[0], metal[1]});
      EXPECT_NEAR(fresnel_conductor(float(c), float(metal[0]), float(metal[1])), expected, 2e-6)
          << "eta " << metal[0] << " k " << metal[1] << " cos " << c;
    }
  // k = 0 is a dielectric: the exact dielectric Fresnel of the same interface.
  for (float c = 0.05f; c <= 1.0f; c += 0.05f) {
    const float cos_t = std::sqrt(1 - (1 - c * c) / (1.5f * 1.5f));
    EXPECT_NEAR(fresnel_conductor(c, 1.5f, 0.0f), fresnel_exact(c, cos_t, 1.0f, 1.5f), 2e-6) << c;
  }
  EXPECT_NEAR(fresnel_conductor(1.0f, 0.2f, 3.0f), (0.64 + 9) / (1.44 + 9), 1e-6) << "((eta-1)^2+k^2)/((eta+1)^2+k^2)";
}

// f(wo, wi) = f(wi, wo) for reflection; for transmission through a rough dielectric, whose f
// has no 1/eta^2 scaling, f(wo, wi) n(wo)^2 = f(wi, wo) n(wi)^2 (Veach 1997, 5.2, for the
// unscaled form). Seen from wi, the frame is turned to wi's side.
TEST(Microfacet, Reciprocity) {
  const Vec3 n = {0, 0, 1};
  for (MaterialKind kind : {MaterialKind::GgxConductor, MaterialKind::GgxDielectric, MaterialKind::GltfMetalRough})
    for (float roughness : {0.2f, 0.5f, 1.0f})
      for (double to : {10.0, 45.0, 75.0})
        for (double ti : {5.0, 40.0, 70.0, 110.0, 150.0, 175.0}) {
          const Material m = test::microfacet_material(kind, roughness);
          const Vec3 wo = direction(to * M_PI / 180, 0.2), wi = direction(ti * M_PI / 180, 2.5);
          for (bool front : {true, false}) {
            const bool transmitted = wi.z < 0;
            const Vec3 n_wi = transmitted ? -n : n;
            const bool front_wi = transmitted ? !front : front;
            const Vec3 a = eval_bsdf(m, wo, wi, n, front).f_cos / std::abs(wi.z);
            const Vec3 b = eval_bsdf(m, wi, wo, n_wi, front_wi).f_cos / std::abs(wo.z);
            float scale = 1;
            if (kind == MaterialKind::GgxDielectric && transmitted) scale = front ? 1.5f * 1.5f : 1 / (1.5f * 1.5f);
            for (int c = 0; c < 3; ++c)
              EXPECT_NEAR(a[c], b[c] * scale, 1e-4 * (1 + std::abs(a[c])))
                  << int(kind) << " r " << roughness << " " << to << " -> " << ti << " front " << front;
          }
        }
}

// The rough dielectric splits each microfacet's light between reflection (F) and
// transmission (1 - F), so with little shadowing (alpha 0.04) its albedo, the integral of
// f cos over the sphere, is near 1 from either side at every angle below grazing, past the
// critical angle too; it never exceeds 1.
TEST(Microfacet, RoughDielectricConservesEnergyBetweenReflectionAndTransmission) {
  const Vec3 n = {0, 0, 1};
  for (bool front : {true, false})
    for (double degrees : {0.0, 20.0, 40.0, 45.0, 60.0, 75.0}) {
      const Material m = test::microfacet_material(MaterialKind::GgxDielectric, 0.2f);
      const Vec3 wo = direction(degrees * M_PI / 180, 0.0);
      auto lobe = [&](Vec3 axis, bool upper) {
        return sphere_integral(
            axis, [&](Vec3 wi) { return (wi.z > 0) == upper ? double(eval_bsdf(m, wo, wi, n, front).f_cos.x) : 0.0; });
      };
      Vec3 refracted;
      float cos_t;
      const bool refracts = refract(-wo, n, front ? 1 / 1.5f : 1.5f, refracted, cos_t);
      // past the critical angle, tilted microfacets still transmit, toward the horizon
      const double reflected = lobe(reflect(-wo, n), true), transmitted = lobe(refracts ? refracted : -n, false);
      const double albedo = reflected + transmitted;
      EXPECT_LE(albedo, 1.0 + 2e-3) << "front " << front << " theta " << degrees;
      EXPECT_GT(albedo, degrees <= 60 ? 0.985 : 0.95) << "front " << front << " theta " << degrees;
    }
}

// Glass of ior 1 (index-matched) has no refraction for Walter's half vector to describe:
// what it transmits goes straight on as a delta (pdf 0, weight the tint), from either side,
// and every sample and value is a number, with Schlick's and the exact Fresnel.
TEST(Microfacet, IndexMatchedRoughGlassTransmitsStraightOn) {
  Material m = test::microfacet_material(MaterialKind::GgxDielectric, 0.5f);
  m.ior = 1.0f;
  m.tint = {0.8f, 0.7f, 0.6f};
  const Vec3 n = {0, 0, 1};
  int transmitted = 0;
  for (FresnelKind fresnel : {FresnelKind::Schlick, FresnelKind::Exact})
    for (bool front : {true, false})
      for (int i = 0; i < 4096; ++i) {
        m.fresnel = fresnel;
        const Vec3 wo = direction(1.5 * (i % 64 + 0.5) / 64, 0.3);
        for (Vec3 wi : {-wo, reflect(-wo, n), direction(2.5, 1.0)}) {
          const BsdfValue v = eval_bsdf(m, wo, wi, n, front);
          ASSERT_TRUE(std::isfinite(v.pdf) && std::isfinite(v.f_cos.x)) << "value " << i;
        }
        BsdfSample s;
        if (!sample_bsdf(m, wo, n, front, (i / 64 + 0.5f) / 64, 0.37f, 0.61f, s)) continue;
        ASSERT_TRUE(std::isfinite(s.pdf) && std::isfinite(s.weight.x)) << "sample " << i;
        if (s.wi.z > 0) continue;
        ++transmitted;
        EXPECT_TRUE(s.specular);
        EXPECT_EQ(s.pdf, 0.0f);
        EXPECT_EQ(s.wi.x, -wo.x);
        EXPECT_EQ(s.wi.z, -wo.z);
        EXPECT_EQ(s.weight.x, m.tint.x);
        EXPECT_EQ(s.weight.z, m.tint.z);
      }
  EXPECT_GT(transmitted, 4 * 4096 * 3 / 4) << "Schlick's reflectance at ior 1 is (1 - cos)^5, small";
}

}  // namespace
}  // namespace tracer
