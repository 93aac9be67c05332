// The microfacet materials' scene keys (tracer/scene/material_reader.cpp): every bad value is
// refused naming the file and the key, and the loader sets the microfacet feature bit.
#include <gtest/gtest.h>

#include "kernel/base/features.h"
#include "test_util.h"

namespace tracer {
namespace {

std::string scene_with(const std::string& material) {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 4], "to": [0, 0, 0], "vfov": 40},
    "film": {"width": 4, "height": 4}, "background": {"type": "constant", "radiance": [1, 1, 1]},
    "materials": {"m": )" +
         material + R"(},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
}

TEST(MicrofacetMaterials, BadValuesAreRefusedNamingTheKey) {
  const auto dir = test::temp_dir("microfacet-materials");
  const struct {
    std::string material, expected;
  } cases[] = {
      {R"({"type": "conductor", "albedo": [1, 1, 1], "roughness": 1.5})",
       "s.json: materials.m.roughness: must be in [0, 1]"},
      {R"({"type": "conductor", "albedo": [1, 1, 1], "roughness": -0.1})", "materials.m.roughness: must be in [0, 1]"},
      {R"({"type": "conductor", "albedo": [1.2, 1, 1]})", "materials.m.albedo: must be in [0, 1]"},
      {R"({"type": "conductor", "eta": [0.2, 0.3, 1.4]})", "materials.m.k: give both eta and k"},
      {R"({"type": "conductor", "eta": [0, 0.3, 1.4], "k": [3, 2, 1]})", "materials.m.eta: must be in [0.01, 100]"},
      {R"({"type": "conductor", "eta": [0.2, 0.3, 1.4], "k": [3, -2, 1]})", "materials.m.k: must be in [0, 1000]"},
      // past 4.3e9 Fresnel's terms overflow to NaN reflectance
      {R"({"type": "conductor", "eta": [5e9, 0.3, 1.4], "k": [3, 2, 1]})", "materials.m.eta: must be in [0.01, 100]"},
      {R"({"type": "conductor", "eta": [0.2, 0.3, 1.4], "k": [3, 5e9, 1]})", "materials.m.k: must be in [0, 1000]"},
      // a denormal ior refracted rays of NaN direction, which crashed the 8-wide tree's walk
      {R"({"type": "rough_dielectric", "ior": 1e-39, "roughness": 0})", "materials.m.ior: must be in [0.01, 100]"},
      {R"({"type": "conductor", "albedo": [1, 1, 1], "eta": [0.2, 0.3, 1.4], "k": [3, 2, 1]})",
       "materials.m.albedo: give albedo"},
      {R"({"type": "rough_dielectric", "ior": 0, "roughness": 0.3})", "materials.m.ior: must be in [0.01, 100]"},
      {R"({"type": "rough_dielectric", "ior": 1.5, "roughness": 2})", "materials.m.roughness: must be in [0, 1]"},
      {R"({"type": "rough_dielectric", "ior": 1.5, "fresnel": "exakt"})", "materials.m.fresnel"},
      {R"({"type": "metal_rough", "base_color": [0.5, 0.5, 0.5], "metallic": 1.01})",
       "materials.m.metallic: must be in [0, 1]"},
      {R"({"type": "metal_rough", "base_color": [0.5, 0.5, 0.5], "transmission": -1})",
       "materials.m.transmission: must be in [0, 1]"},
      {R"({"type": "metal_rough", "base_color": [0.5, 0.5, 0.5], "ior": -1.5})",
       "materials.m.ior: must be in [0.01, 100]"},
      {R"({"type": "metal_rough", "base_color": [0.5, 0.5, 0.5], "roughnes": 0.5})", "roughnes"},
      {R"({"type": "metal_rough", "base_color": [0.5, 0.5, 0.5], "roughness": "rough"})",
       "materials.m.roughness: expected a number"},
  };
  for (const auto& c : cases) test::expect_load_error(dir, scene_with(c.material), c.expected);
}

TEST(MicrofacetMaterials, EachKindSetsTheMicrofacetFeature) {
  for (const char* m : {R"({"type": "conductor", "eta": [0.2, 0.9, 1.1], "k": [3.9, 2.4, 2.1], "roughness": 0.3})",
                        R"({"type": "rough_dielectric", "ior": 1.5, "roughness": 0.3})",
                        R"({"type": "metal_rough", "base_color": [0.5, 0.5, 0.5]})"}) {
    const Scene s = test::scene_from(scene_with(m));
    EXPECT_TRUE(s.features & kFeatureMicrofacet) << m;
  }
}

}  // namespace
}  // namespace tracer
