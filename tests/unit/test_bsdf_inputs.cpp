// Which random numbers sample_bsdf reads (kernel/material/bsdf.h): the path tracer draws the lobe
// choice only where bsdf_uses_choice says so and the direction pair only where the material is
// not specular (kernel/integrator/path.h), so a material that read a number it was not given
// would see 0 instead. Every material kind, smooth and rough, at many outgoing directions on
// both sides: a number the flags call unread changes no sample bit, and a number they call
// read changes some.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "kernel/material/bsdf.h"
#include "microfacet_material.h"

namespace tracer {
namespace {

// The microfacet tests' material, with Phong's and an emitter's colours too.
Material material(MaterialKind kind, float roughness) {
  Material m = test::microfacet_material(kind, roughness);
  m.specular = {0.5f, 0.5f, 0.5f};
  m.shininess = 20.0f;
  m.radiance = {1.0f, 1.0f, 1.0f};
  return m;
}

struct Outcome {
  bool ok;
  BsdfSample s;
  bool operator==(const Outcome& o) const {
    return ok == o.ok && std::memcmp(&s.wi, &o.s.wi, sizeof s.wi) == 0 &&
           std::memcmp(&s.weight, &o.s.weight, sizeof s.weight) == 0 &&
           std::memcmp(&s.pdf, &o.s.pdf, sizeof s.pdf) == 0 && s.specular == o.s.specular;
  }
};

Outcome sample(const Material& m, Vec3 wo, bool front, float u_choice, float u1, float u2) {
  Outcome o{};
  o.ok = sample_bsdf(m, wo, {0.0f, 0.0f, 1.0f}, front, u_choice, u1, u2, o.s);
  return o;
}

TEST(BsdfInputs, UnreadNumbersChangeNoSampleAndReadOnesDo) {
  const MaterialKind kinds[] = {MaterialKind::Lambert,       MaterialKind::PhongMetal,    MaterialKind::Dielectric,
                                MaterialKind::Phong,         MaterialKind::Emissive,      MaterialKind::GgxConductor,
                                MaterialKind::GgxDielectric, MaterialKind::GltfMetalRough};
  for (const MaterialKind kind : kinds) {
    for (const float roughness : {0.0f, 0.3f}) {
      const Material m = material(kind, roughness);
      SCOPED_TRACE("kind " + std::to_string(static_cast<int>(kind)) + " roughness " + std::to_string(roughness));
      bool choice_changed = false, direction_changed = false;
      for (int i = 0; i < 64; ++i) {
        const float cos_o = 0.02f + 0.96f * (static_cast<float>(i) + 0.5f) / 64.0f;
        const Vec3 wo = normalize(Vec3{0.6f * (1.0f - cos_o), 0.3f, cos_o});
        for (const bool front : {true, false}) {
          const Outcome base = sample(m, wo, front, 0.05f, 0.3f, 0.7f);
          for (const float u_choice : {0.0f, 0.5f, 0.999f}) {
            const bool same = sample(m, wo, front, u_choice, 0.3f, 0.7f) == base;
            if (!bsdf_uses_choice(m)) {
              EXPECT_TRUE(same) << "u_choice " << u_choice;
            }
            choice_changed |= !same;
          }
          for (const float u : {0.0f, 0.5f, 0.999f}) {
            const bool same = sample(m, wo, front, 0.05f, u, 1.0f - u * 0.5f) == base;
            if (is_specular(m)) {
              EXPECT_TRUE(same) << "u " << u;
            }
            direction_changed |= !same;
          }
        }
      }
      EXPECT_EQ(choice_changed, bsdf_uses_choice(m)) << "the lobe choice";
      EXPECT_EQ(direction_changed, !is_specular(m)) << "the direction pair";
    }
  }
}

}  // namespace
}  // namespace tracer
