// `--effects`: each Whitted effect can be switched off for `tracer bench device`, and
// switching one off removes exactly its rays; all effects is the default image, bit for bit.
#include <gtest/gtest.h>

#include <cstring>

#include "io/input_error.h"
#include "options/effects.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

TEST(Effects, ParseAndName) {
  EXPECT_EQ(parse_effects("all", "--effects"), kEffectAll);
  EXPECT_EQ(parse_effects("none", "--effects"), kEffectNone);
  EXPECT_EQ(parse_effects("shadows,refractions", "--effects"), kEffectShadows | kEffectRefraction);
  EXPECT_EQ(effects_name(kEffectNone), "shading only");
  EXPECT_EQ(effects_name(kEffectReflection), "shading + reflections");
  EXPECT_EQ(effects_name(kEffectAll), "all");
  for (const std::string list : {"shadow", "shadows,,reflections", ""}) {
    try {
      parse_effects(list, "scene.json: render.effects");
      ADD_FAILURE() << "accepted \"" << list << "\"";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("scene.json: render.effects"), std::string::npos) << e.what();
    }
  }
  // effects_text is the form parse_effects reads back, for every mask.
  for (uint32_t mask = 0; mask <= kEffectAll; ++mask)
    EXPECT_EQ(parse_effects(effects_text(static_cast<Effects>(mask)), "--effects"), mask);
}

// The Cornell box: a mirror sphere, a glass sphere, a point light; small and fast.
RenderStats render_with(const std::string& scene, std::optional<uint32_t> effects, Image& image) {
  RenderOverrides ov;
  if (effects) ov.effects = static_cast<Effects>(*effects);
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
