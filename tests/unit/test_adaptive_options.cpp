// Adaptive sampling's options through the CLI and the scene file: every bad value or
// combination exits 2 with a message naming the key or flag, and writes nothing; a good
// one writes the image and the sample map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <tuple>

#include "image/image_io.h"
#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

std::string scene_text(const std::string& render) {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40},
    "film": {"width": 8, "height": 6}, "render": {"integrator": "path", "spp": 64, )" +
         render + R"(}, "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "background": {"type": "constant", "radiance": [1, 1, 1]},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
}

class AdaptiveOptions : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::temp_dir("adaptive-options"); }
  void TearDown() override { fs::remove_all(dir_); }

  std::string scene(const std::string& render) {
    std::ofstream(dir_ / "s.json", std::ios::binary) << scene_text(render);
    return (dir_ / "s.json").string();
  }
  std::string out() const { return " -o " + (dir_ / "out.exr").string(); }

  void expect_refused(const std::string& args, const std::string& expected) {
    std::string output;
    EXPECT_EQ(test::run_tracer(args, &output), 2) << args << "\n" << output;
    EXPECT_NE(output.find(expected), std::string::npos) << args << "\n" << output;
    EXPECT_FALSE(fs::exists(dir_ / "out.exr")) << args;
    EXPECT_FALSE(fs::exists(dir_ / "out.partial")) << args;
    EXPECT_FALSE(fs::exists(dir_ / "map.exr")) << args;
  }

  fs::path dir_;
};

TEST_F(AdaptiveOptions, BadThresholdsAreRefused) {
  const std::string s = scene(R"("sampler": "sobol")");
  for (const char* bad : {"-0.1", "0", "0.0", "nan", "inf", "1e999", "''", "' 0.1'", "0x1p-3", "1e-3", "2000000"})
    expect_refused("render " + s + " --noise-threshold " + bad + out(), "--noise-threshold");
  for (const char* bad : {"-0.1", "0", "nan", "1e999", "''"})
    expect_refused("render " + s + " --target-error " + bad + out(), "--target-error");
  for (const char* bad : {"0", "-1", "\"0.1\"", "true", "1e7"})
    expect_refused("render " + scene(std::string(R"("noise_threshold": )") + bad) + out(), "render.noise_threshold");
  // Positive as decimals, but 0 (off: a uniform render) or subnormal as the float the renderer holds.
  for (const char* tiny : {"1e-50", "1e-40"})
    expect_refused("render " + scene(std::string(R"("sampler": "sobol", "target_error": )") + tiny) + out(),
                   "render.target_error");
  const std::string sobol = scene(R"("sampler": "sobol")");  // the scene file again, as at the start
  expect_refused("render " + sobol + " --noise-threshold 0." + std::string(49, '0') + "1" + out(), "smallest normal");
  // One sample has no two halves to estimate an error from (the estimate was -nan, exit 0).
  expect_refused("render " + sobol + " --spp 1 --target-error 0.1" + out(), "command line --spp: adaptive sampling");
}

TEST_F(AdaptiveOptions, BadMinimumsAreRefused) {
  expect_refused("render " + scene(R"("noise_threshold": 0.1, "min_spp": 128)") + out(), "render.min_spp");
  expect_refused("render " + scene(R"("noise_threshold": 0.1)") + " --min-spp 65" + out(), "--min-spp");
  expect_refused("render " + scene(R"("noise_threshold": 0.1)") + " --min-spp 1" + out(), "at least 2");
  expect_refused("render " + scene(R"("min_spp": 8)") + out(), "needs noise_threshold");
}

TEST_F(AdaptiveOptions, CombinationsThatCannotBeAdaptiveAreRefused) {
  expect_refused("render " + scene(R"("noise_threshold": 0.1, "sampler": "stratified")") + out(),
                 "stochastic or sobol");
  expect_refused("render " + scene(R"("noise_threshold": 0.1, "sampler": "grid")") + out(), "stochastic or sobol");
  // An EXR sample map of counts above 2^24 (16777217 was written as 16777216): refused before the render.
  expect_refused("render " + scene(R"("noise_threshold": 0.1)") + " --spp 16777217 --sample-map " +
                     (dir_ / "map.exr").string() + out(),
                 "a float image holds counts exactly only up to 2^24");
  expect_refused(
      "render " + scene(R"("noise_threshold": 0.1)") + " --samples 0:32 -o " + (dir_ / "out.partial").string(),
      "cannot be split into sample ranges");
  expect_refused("render " + scene("\"seed\": 1") + " --sample-map " + (dir_ / "map.exr").string() + out(),
                 "only an adaptive render");
  expect_refused(
      "slurm submit " + scene(R"("noise_threshold": 0.1)") + " --parts 2 --dir " + (dir_ / "job").string() + out(),
      "tracer slurm cannot split it");
  EXPECT_FALSE(fs::exists(dir_ / "job"));
  const std::string s = scene(R"("noise_threshold": 0.1)");
  const std::string before = test::read_file(s);
  expect_refused("render " + s + " --sample-map " + s + out(), "--sample-map");
  EXPECT_EQ(test::read_file(s), before);
}

TEST_F(AdaptiveOptions, AnAdaptiveRenderWritesItsImageAndSampleMap) {
  std::string output;
  ASSERT_EQ(test::run_tracer("render " + scene(R"("noise_threshold": 0.05, "min_spp": 4)") + " --sample-map " +
                                 (dir_ / "map.exr").string() + " --stats " + (dir_ / "stats.json").string() + out(),
                             &output),
            0)
      << output;
  EXPECT_TRUE(fs::exists(dir_ / "out.exr"));
  EXPECT_TRUE(fs::exists(dir_ / "map.exr"));
  const std::string stats = test::read_file(dir_ / "stats.json");
  EXPECT_NE(stats.find("\"checkpoints\": [\n      4,\n      8,\n      16,\n      32,\n      64\n    ]"),
            std::string::npos)
      << stats;
  EXPECT_NE(output.find("spp on average"), std::string::npos) << output;
  // The EXR map holds the counts; a PNG map the counts over spp, so that it shows.
  const Image map = read_image((dir_ / "map.exr").string());
  ASSERT_EQ(test::run_tracer("render " + scene(R"("noise_threshold": 0.05, "min_spp": 4)") + " --quiet --sample-map " +
                                 (dir_ / "map.png").string() + out(),
                             &output),
            0)
      << output;
  const Image png = read_image((dir_ / "map.png").string());
  ASSERT_EQ(png.rgb.size(), map.rgb.size());
  float fewest = 64.0f, most = 0.0f;
  for (size_t i = 0; i < map.rgb.size(); ++i) {
    fewest = std::min(fewest, map.rgb[i]), most = std::max(most, map.rgb[i]);
    const float expected = map.rgb[i] / 64.0f,
                srgb = expected <= 0.0031308f ? 12.92f * expected : 1.055f * std::pow(expected, 1 / 2.4f) - 0.055f;
    EXPECT_NEAR(png.rgb[i], srgb, 0.5f / 255.0f + 1e-6f) << "value " << i << ": " << map.rgb[i] << " samples";
  }
  EXPECT_EQ(fewest, 4.0f) << "some pixels stop at min_spp";
  EXPECT_EQ(most, 64.0f) << "some pixels run to spp";
}

// bench converge's adaptive series is checked before the reference and the uniform series
// render (it refused only when it reached the series): nothing printed, no reference cached.
TEST_F(AdaptiveOptions, BenchConvergeRefusesItsAdaptiveSeriesBeforeAnyRender) {
  const std::string outputs = " --spp 1,4 --csv " + (dir_ / "c.csv").string() + " --plot " + (dir_ / "c.png").string();
  for (const auto& [render, args, expected] :
       {std::tuple{R"("sampler": "grid")", " --thresholds 0.05", "not grid"},
        {R"("sampler": "stochastic")", " --thresholds 0.05 --adaptive-spp 16 --min-spp 32",
         "--min-spp: 32 is above spp 16"}}) {
    std::string output;
    const std::string command = "bench converge " + scene(render) + outputs + args;
    EXPECT_EQ(test::run_command("cd " + dir_.string() + " && " + TRACER_BINARY + " " + command, &output), 2) << output;
    EXPECT_NE(output.find(expected), std::string::npos) << output;
    EXPECT_EQ(output.find("tracer bench converge"), std::string::npos) << "the reference rendered first:\n" << output;
    EXPECT_FALSE(fs::exists(dir_ / "s-converge-ref.exr"));
  }
}

}  // namespace
}  // namespace tracer
