// `--effects`: each Whitted effect can be switched off for `tracer bench device`, and
// switching one off removes exactly its rays; all effects is the default image, bit for bit.
#include <gtest/gtest.h>

#include <cstring>

#include "render/effects.h"
#include "io/input_error.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

TEST(Effects, ParseAndName) {
  EXPECT_EQ(parse_effects("all"), kEffectAll);
  EXPECT_EQ(parse_effects("none"), 0u);
  EXPECT_EQ(parse_effects("shadows,refractions"), kEffectShadows | kEffectRefraction);
  EXPECT_EQ(effects_name(0), "shading only");
  EXPECT_EQ(effects_name(kEffectReflection), "shading + reflections");
  EXPECT_EQ(effects_name(kEffectAll), "all");
  EXPECT_THROW(parse_effects("shadow"), InputError);
  EXPECT_THROW(parse_effects("shadows,,reflections"), InputError);
}

// The Cornell box: a mirror sphere, a glass sphere, a point light; small and fast.
RenderStats render_with(const std::string& scene, std::optional<uint32_t> effects, Image& image) {
  RenderOverrides ov;
  ov.effects = effects;
  ov.width = 64;
  ov.height = 48;
  RenderStats stats;
  image = render_cpu(load_scene(test::source_path(scene), ov), 1, stats);
  return stats;
}

TEST(Effects, EachSwitchRemovesItsRays) {
  Image all, fallback, none, shadows, mirrors;
  const RenderStats s_all = render_with("scenes/cornell-box.json", kEffectAll, all);
  render_with("scenes/cornell-box.json", std::nullopt, fallback);
  EXPECT_EQ(std::memcmp(all.rgb.data(), fallback.rgb.data(), all.rgb.size() * sizeof(float)), 0);
  const RenderStats s_none = render_with("scenes/cornell-box.json", 0u, none);
  EXPECT_EQ(s_none.rays.shadow, 0u);
  EXPECT_EQ(s_none.rays.secondary, 0u);
  EXPECT_EQ(s_none.rays.camera, s_all.rays.camera);
  const RenderStats s_shadows = render_with("scenes/cornell-box.json", kEffectShadows, shadows);
  EXPECT_GT(s_shadows.rays.shadow, 0u);
  EXPECT_EQ(s_shadows.rays.secondary, 0u);
  const RenderStats s_mirrors = render_with("scenes/cornell-box.json", kEffectReflection, mirrors);
  EXPECT_EQ(s_mirrors.rays.shadow, 0u);
  EXPECT_GT(s_mirrors.rays.secondary, 0u);
  EXPECT_LT(s_mirrors.rays.secondary, s_all.rays.secondary) << "refraction rays are gone";
}

}  // namespace
}  // namespace tracer
