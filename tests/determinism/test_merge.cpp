// Sample ranges (docs/determinism.md rule 5): `render --samples A:B` parts merged by `tracer merge`
// equal the whole render bit for bit, however the samples are split; merge refuses parts
// that leave a gap, overlap, or come from another render.
#include <gtest/gtest.h>

#include <fstream>

#include "test_util.h"

namespace tracer {
namespace {

struct Split {
  const char* scene;
  const char* extra;  // render options
  std::vector<std::pair<int, int>> ranges;
};

class MergeSplits : public testing::TestWithParam<Split> {};

TEST_P(MergeSplits, MergedPartsEqualTheWholeRender) {
  const auto dir = test::temp_dir("merge");
  const std::string scene = test::source_path(GetParam().scene), extra = GetParam().extra;
  std::string output;
  ASSERT_EQ(test::run_tracer("render " + scene + " --quiet " + extra + " -o " + (dir / "whole.exr").string(), &output),
            0)
      << output;
  std::string parts;
  for (const auto& [a, b] : GetParam().ranges) {
    const std::string part = (dir / ("part" + std::to_string(a) + ".partial")).string();
    ASSERT_EQ(test::run_tracer("render " + scene + " --quiet " + extra + " --threads " + std::to_string(1 + a % 3) +
                                   " --samples " + std::to_string(a) + ":" + std::to_string(b) + " -o " + part,
                               &output),
              0)
        << output;
    parts = part + " " + parts;  // merge takes the parts in any order
  }
  ASSERT_EQ(test::run_tracer("merge " + parts + "-o " + (dir / "merged.exr").string(), &output), 0) << output;
  EXPECT_EQ(test::run_tracer(
                "compare " + (dir / "whole.exr").string() + " " + (dir / "merged.exr").string() + " --fail 0", &output),
            0)
      << output;
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, MergeSplits,
    testing::Values(
        Split{"scenes/features/thin-lens.json", "", {{0, 1}, {1, 5}, {5, 16}}},
        Split{
            "scenes/cornell-box.json", "--width 96 --height 72 --sampler stochastic --spp 7", {{0, 3}, {3, 4}, {4, 7}}},
        Split{"scenes/features/refraction.json", "--sampler stratified --spp 9", {{0, 4}, {4, 9}}},
        Split{"scenes/cornell-box-path.json", "--width 64 --height 48 --spp 12", {{0, 5}, {5, 6}, {6, 12}}},
        Split{"scenes/features/path-materials.json", "--width 48 --height 36 --spp 8 --nee off", {{0, 3}, {3, 8}}}));

TEST(Merge, RefusesGapsOverlapsAndOtherRenders) {
  const auto dir = test::temp_dir("merge-bad");
  const std::string scene = test::source_path("scenes/features/thin-lens.json");
  const auto part = [&](const std::string& name, const std::string& args) {
    const std::string path = (dir / (name + ".partial")).string();
    EXPECT_EQ(test::run_tracer("render " + scene + " --quiet " + args + " -o " + path), 0);
    return path;
  };
  const std::string a = part("a", "--samples 0:4"), b = part("b", "--samples 4:16"), c = part("c", "--samples 2:16"),
                    other = part("other", "--seed 9 --samples 4:16");
  const std::string out = (dir / "out.exr").string();
  std::string output;
  EXPECT_EQ(test::run_tracer("merge " + a + " -o " + out, &output), 2) << output;
  EXPECT_NE(output.find("no part holds samples [4, 16)"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer("merge " + a + " " + c + " -o " + out, &output), 2) << output;
  EXPECT_NE(output.find("overlap"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer("merge " + a + " " + other + " -o " + out, &output), 2) << output;
  EXPECT_NE(output.find("not a part of the same render"), std::string::npos) << output;
  std::ofstream(dir / "junk.partial") << "tracer-partial/1\n{}\n";
  EXPECT_EQ(test::run_tracer("merge " + (dir / "junk.partial").string() + " -o " + out, &output), 2) << output;
  EXPECT_NE(output.find("junk.partial"), std::string::npos) << output;
  EXPECT_FALSE(std::filesystem::exists(out)) << "a refused merge writes nothing";
  EXPECT_EQ(test::run_tracer("merge " + b + " " + a + " -o " + out, &output), 0) << output;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tracer
