// Closed-form optics: Snell's law, the critical angle of total internal reflection,
// Schlick's and the exact Fresnel reflectance at their limits.
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/material/bsdf.h"
#include "kernel/shading/optics.h"
#include "test_util.h"

using namespace tracer;

namespace {
// A unit direction hitting the surface z = 0 (normal +z) at angle theta from the normal.
Vec3 incident(double theta) {
  return {static_cast<float>(std::sin(theta)), 0.0f, static_cast<float>(-std::cos(theta))};
}
double sin_to_normal(Vec3 d, Vec3 n) { return length(cross(d, n)); }
}  // namespace

TEST(Optics, RefractionSatisfiesSnellsLaw) {
  const Vec3 n = {0, 0, 1};
  for (const auto& [n1, n2] : {std::pair{1.0f, 1.5f}, {1.5f, 1.0f}, {1.0f, 2.42f}, {1.33f, 1.0f}, {1.0f, 1.000001f}}) {
    for (double theta = 0.0; theta < 1.5707; theta += 0.001) {
      const Vec3 d = incident(theta);
      Vec3 t;
      float cos_t;
      if (!refract(d, n, n1 / n2, t, cos_t)) {
        EXPECT_GT(n1 * std::sin(theta), n2 * (1.0 - 1e-6)) << "TIR below the critical angle";
        continue;
      }
      EXPECT_NEAR(length(t), 1.0, 1e-6);
      EXPECT_NEAR(n1 * sin_to_normal(d, n), n2 * sin_to_normal(t, n), 1e-6) << n1 << " -> " << n2 << " at " << theta;
      EXPECT_LT(t.z, 0.0f);  // continues into the second medium
    }
  }
}

// Total internal reflection begins at theta_c = asin(n2 / n1), to 1e-5 radians.
TEST(Optics, TotalInternalReflectionStartsAtCriticalAngle) {
  const Vec3 n = {0, 0, 1};
  for (const auto& [n1, n2] : {std::pair{1.5f, 1.0f}, {2.42f, 1.0f}, {1.33f, 1.0f}, {4.0f, 1.0f}}) {
    const double critical = std::asin(static_cast<double>(n2) / n1);
    Vec3 t;
    float cos_t;
    EXPECT_TRUE(refract(incident(critical - 1e-5), n, n1 / n2, t, cos_t)) << n1;
    EXPECT_FALSE(refract(incident(critical + 1e-5), n, n1 / n2, t, cos_t)) << n1;
    // Just below the critical angle the transmitted ray grazes the surface.
    refract(incident(critical - 1e-5), n, n1 / n2, t, cos_t);
    EXPECT_LT(cos_t, 0.01f);
  }
}

TEST(Optics, ReflectionMirrorsTheAngle) {
  const Vec3 d = incident(0.7), n = {0, 0, 1};
  const Vec3 r = reflect(d, n);
  EXPECT_FLOAT_EQ(r.x, d.x);
  EXPECT_FLOAT_EQ(r.z, -d.z);
}

TEST(Optics, SchlickEqualsR0AtNormalIncidenceAndOneAtGrazing) {
  for (const float ior : {1.0f, 1.33f, 1.5f, 2.42f, 4.0f}) {
    const float r0 = ((1.0f - ior) / (1.0f + ior)) * ((1.0f - ior) / (1.0f + ior));
    EXPECT_EQ(fresnel_schlick(1.0f, 1.0f, ior), r0);
    EXPECT_NEAR(fresnel_schlick(0.0f, 1.0f, ior), 1.0f, 1e-7f);
    float previous = r0;
    for (float c = 1.0f; c >= 0.0f; c -= 0.01f) {  // rises monotonically towards grazing
      const float f = fresnel_schlick(c, 1.0f, ior);
      EXPECT_GE(f, previous);
      EXPECT_LE(f, 1.0f);
      previous = f;
    }
  }
}

// Reflectance is reciprocal (Helmholtz): light crossing an interface one way reflects as much
// as light crossing it back along the same two directions. Schlick's approximation keeps
// that by taking the cosine on the optically thinner side (Schlick 1994) from either side,
// so from inside the glass it must equal the outside value bit for bit, and reach 1 at the
// critical angle, where the outside angle is grazing.
TEST(Optics, SchlickIsTheSameFromEitherSideOfTheInterface) {
  for (const float ior : {1.33f, 1.5f, 2.42f}) {
    for (double theta = 0.0; theta < 1.5707; theta += 0.01) {
      const Vec3 d = incident(theta), n = {0.0f, 0.0f, 1.0f};
      Vec3 t;
      float cos_t;
      ASSERT_TRUE(refract(d, n, 1.0f / ior, t, cos_t));
      const float cos_i = static_cast<float>(std::cos(theta));
      const float outside = dielectric_reflectance(FresnelKind::Schlick, cos_i, cos_t, 1.0f, ior);
      const float inside = dielectric_reflectance(FresnelKind::Schlick, cos_t, cos_i, ior, 1.0f);
      EXPECT_EQ(inside, outside) << "ior " << ior << " at " << theta;
    }
    const float at_critical =
        dielectric_reflectance(FresnelKind::Schlick, std::sqrt(1.0f - 1.0f / (ior * ior)), 0.0f, ior, 1.0f);
    EXPECT_NEAR(at_critical, 1.0f, 1e-6f) << "ior " << ior;
  }
}

TEST(Optics, ExactFresnelLimits) {
  for (const float ior : {1.33f, 1.5f, 2.42f}) {
    const float r0 = ((1.0f - ior) / (1.0f + ior)) * ((1.0f - ior) / (1.0f + ior));
    EXPECT_NEAR(fresnel_exact(1.0f, 1.0f, 1.0f, ior), r0, 1e-7f);
    // Grazing incidence from air: cos_i -> 0 reflects everything.
    const float cos_t = std::sqrt(1.0f - 1.0f / (ior * ior));
    EXPECT_NEAR(fresnel_exact(0.0f, cos_t, 1.0f, ior), 1.0f, 1e-6f);
  }
  // IOR 1: no interface, no reflection at any angle.
  for (float c = 0.05f; c <= 1.0f; c += 0.05f) EXPECT_EQ(fresnel_exact(c, c, 1.0f, 1.0f), 0.0f);
}

// Over the indices a scene may give (docs/scene-format.md: ior and eta in [0.01, 100], k in
// [0, 1000]), from either side of the interface, every reflectance is a number in [0, 1] and
// every refracted direction a unit vector: the range stops short of where the squares and
// 1 / ior overflow (a denormal ior refracted rays of NaN direction).
TEST(Optics, FresnelAndRefractionStayFiniteOverTheAcceptedIndices) {
  const Vec3 n = {0, 0, 1};
  for (const float ior : {0.01f, 0.1f, 1.0f, 1.5f, 10.0f, 100.0f})
    for (const float eta : {ior, 1.0f / ior})
      for (double theta = 0.0; theta < 1.5707; theta += 0.01) {
        const float cos_i = static_cast<float>(std::cos(theta));
        for (const FresnelKind model : {FresnelKind::Schlick, FresnelKind::Exact}) {
          const float r = dielectric_reflectance_at(model, cos_i, 1.0f, eta);
          EXPECT_TRUE(r >= 0.0f && r <= 1.0f) << "ior " << eta << " theta " << theta << ": " << r;
        }
        Vec3 t;
        float cos_t;
        if (refract(incident(theta), n, eta, t, cos_t)) {
          EXPECT_NEAR(length(t), 1.0, 1e-5) << "eta " << eta << " theta " << theta;
        }
      }
  for (const float eta : {0.01f, 0.2f, 1.0f, 100.0f})
    for (const float k : {0.0f, 0.01f, 3.0f, 1000.0f})
      for (float c = 0.0f; c <= 1.0f; c += 0.01f) {
        const float r = fresnel_conductor(c, eta, k);
        EXPECT_TRUE(r >= 0.0f && r <= 1.0f) << "eta " << eta << " k " << k << " cos " << c << ": " << r;
      }
}

// The path tracer's dielectric as sample_bsdf draws it (kernel/material/bsdf.h), from outside
// (front) and from inside the glass: a refraction obeys Snell's law n_in sin(theta_i) =
// n_out sin(theta_t) and leaves on the far side; beyond the critical angle arcsin(1 / ior),
// reached only from inside, every choice reflects about the normal (total internal reflection).
TEST(Optics, PathTracerDielectricRefractsBySnellsLawFromEitherSide) {
  Material glass{};
  glass.kind = MaterialKind::Dielectric;
  glass.fresnel = FresnelKind::Exact;
  glass.tint = {1.0f, 1.0f, 1.0f};
  glass.ior = 1.5f;
  const double critical = std::asin(1.0 / 1.5);
  for (const bool front : {true, false}) {
    const double n_in = front ? 1.0 : 1.5, n_out = front ? 1.5 : 1.0;
    // n is the normal on wo's side, as the integrator passes it; wo points back along the ray.
    const Vec3 n = {0.0f, 0.0f, 1.0f};
    for (double theta = 0.01; theta < 1.55; theta += 0.01) {
      const Vec3 d = incident(theta), wo = -d;
      BsdfSample s{};
      ASSERT_TRUE(sample_bsdf(glass, wo, n, front, 0.9999f, 0.5f, 0.5f, s));
      ASSERT_TRUE(s.specular);
      if (!front && theta > critical + 1e-4) {
        const Vec3 mirror = reflect(d, n);
        EXPECT_NEAR(length(s.wi - mirror), 0.0, 1e-6) << "inside, beyond the critical angle, at " << theta;
        continue;
      }
      if (!front && theta > critical - 1e-4) continue;  // within rounding of the critical angle
      // u_choice near 1 refracts wherever the Fresnel reflectance is below it.
      ASSERT_LT(s.wi.z, 0.0f) << (front ? "outside" : "inside") << " at " << theta << ": did not refract";
      EXPECT_NEAR(n_in * std::sin(theta), n_out * sin_to_normal(s.wi, n), 2e-6)
          << (front ? "outside" : "inside") << " at " << theta;
    }
  }
}

// The Whitted tracer splits a ray at glass into Fresnel-weighted reflected and refracted
// rays; the path tracer picks one of them with the Fresnel probability. With the same camera
// rays (the same sampler, seed and spp), the same depth, no Russian roulette and no lights,
// the path tracer's pixel is therefore an unbiased estimate of the Whitted pixel (the same
// sum, evaluated by sampling). Every path returns throughput 1 times a background radiance in
// [0, 1], so a pixel's error has standard deviation at most 1 / (2 sqrt(spp)) (Popoviciu);
// every pixel must lie within 5 of those. A glass ball makes every ray refract in and out.
TEST(Optics, WhittedGlassIsThePathTracersExpectation) {
  const auto dir = test::temp_dir("optics-glass");
  const auto scene = [](const char* integrator) {
    return std::string(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0.3, 3], "to": [0, 0, 0], "vfov": 45},
      "film": {"width": 16, "height": 16},
      "render": {"integrator": ")") +
           integrator + R"(", "sampler": "stochastic", "spp": 1024, "max_depth": 8, "rr_depth": 64, "seed": 5},
      "background": {"type": "gradient", "zenith": [1, 0.6, 0.2], "horizon": [0, 0.1, 0.9]},
      "materials": {"glass": {"type": "dielectric", "ior": 1.5, "fresnel": "exact"}},
      "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass"}]})";
  };
  const Image whitted = test::render_in(dir, scene("whitted"));
  const Image path = test::render_in(dir, scene("path"));
  ASSERT_EQ(whitted.rgb.size(), path.rgb.size());
  const double bound = 5.0 * 0.5 / std::sqrt(1024.0);
  size_t outside = 0;
  for (size_t i = 0; i < path.rgb.size(); ++i) outside += std::abs(path.rgb[i] - whitted.rgb[i]) > bound;
  EXPECT_EQ(outside, 0u) << "of " << path.rgb.size() << " pixel channels beyond " << bound;
  std::filesystem::remove_all(dir);
}
