// Images do not depend on the thread count: bit for bit. (Acceleration structures:
// test_accel_identity.cpp.)
#include <gtest/gtest.h>

#include <cstring>

#include "image/image_io.h"
#include "options/enum_names.h"
#include "render/render_cpu.h"
#include "test_util.h"

using namespace tracer;

namespace {

bool same_bits(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height &&
         std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

Image render_file(const std::string& scene, const RenderOverrides& ov, int threads) {
  RenderStats stats;
  return render_cpu(load_scene(test::source_path(scene), ov), threads, stats);
}

}  // namespace

// Through the CLI: --threads 1, 2 and 7 write identical EXR files.
TEST(Determinism, ThreadCountsGiveIdenticalImagesThroughCli) {
  const auto dir = test::temp_dir("threads");
  const std::string scene = test::source_path("scenes/cornell-box.json");
  std::vector<Image> images;
  for (int threads : {1, 2, 7}) {
    const std::string out = (dir / ("t" + std::to_string(threads) + ".exr")).string();
    ASSERT_EQ(test::run_tracer("render " + scene + " --quiet --width 160 --height 120 --threads " +
                               std::to_string(threads) + " -o " + out),
              0);
    images.push_back(read_image(out));
  }
  EXPECT_TRUE(same_bits(images[0], images[1]));
  EXPECT_TRUE(same_bits(images[0], images[2]));
  std::filesystem::remove_all(dir);
}

// Random samplers and the thin lens as well: the counter-based RNG has no per-thread state.
TEST(Determinism, StochasticSamplersAcrossThreadCounts) {
  for (const char* sampler : {"stochastic", "stratified"}) {
    RenderOverrides ov;
    ov.sampler = parse_enum<SamplerKind>(sampler, "sampler");
    ov.spp = 4;
    ov.width = 48;
    ov.height = 36;
    const Image one = render_file("scenes/features/thin-lens.json", ov, 1);
    EXPECT_TRUE(same_bits(one, render_file("scenes/features/thin-lens.json", ov, 2))) << sampler;
    EXPECT_TRUE(same_bits(one, render_file("scenes/features/thin-lens.json", ov, 7))) << sampler;
  }
}
