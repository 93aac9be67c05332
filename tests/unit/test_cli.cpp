// The CLI end to end: every kind of bad input gets one clear error naming the file and
// key, exit code 2, and no output file; compare's exit codes; info's report.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

#include "io/json_reader.h"
#include "test_util.h"

using namespace tracer;

namespace {

const char* kGoodScene = R"({"format": "tracer-scene/1",
  "camera": {"from": [0, 0, 5], "to": [0, 0, 0], "vfov": 40},
  "film": {"width": 16, "height": 12},
  "render": {"spp": 1, "sampler": "center"},
  "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
  "lights": [{"type": "point", "position": [0, 3, 3], "intensity": [10, 10, 10]}],
  "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? s : s.replace(at, from.size(), to);
}

struct BadInput {
  const char* name;
  std::string scene;     // scene text ("" = the file does not exist)
  std::string args;      // extra CLI arguments
  std::string expected;  // must appear in the message
};

// Names the case in test listings instead of gtest's byte dump.
void PrintTo(const BadInput& in, std::ostream* os) { *os << in.name; }

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

std::vector<BadInput> bad_inputs() {
  const std::string g = kGoodScene;
  return {
      {"MalformedJson", replace(g, "\"vfov\": 40}", "\"vfov\": 40,}"), "", "inline.json:2:"},
      {"UnknownKey", replace(g, "\"radius\": 1", "\"radius\": 1, \"radiuss\": 2"), "",
       "shapes[0].radiuss: unknown key"},
      {"WrongType", replace(g, "\"radius\": 1", "\"radius\": \"1\""), "",
       "shapes[0].radius: expected a number, got \"1\""},
      {"MissingFile", "", "", "cannot open scene file"},
      {"MissingObj",
       replace(g, R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"})",
               R"({"type": "mesh", "file": "nope.obj", "material": "m"})"),
       "", "shapes[0].file: "},
      {"NegativeRadius", replace(g, "\"radius\": 1", "\"radius\": -1"), "", "shapes[0].radius: must be > 0"},
      {"ZeroAreaQuad",
       replace(g, R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"})",
               R"({"type": "quad", "corner": [0, 0, 0], "u": [1, 0, 0], "v": [2, 0, 0], "material": "m"})"),
       "", "shapes[0]: zero-area quad"},
      {"ZeroAreaTriangle",
       replace(g, R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"})",
               R"({"type": "triangle", "vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]], "material": "m"})"),
       "", "shapes[0].vertices: zero-area triangle"},
      {"MeshOfZeroAreaTriangles",
       replace(
           g, R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"})",
           R"({"type": "mesh", "positions": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "indices": [[0, 1, 1], [2, 2, 2]], "material": "m"})"),
       "", "shapes[0].indices: every triangle of the mesh has zero area"},
      {"InfiniteNumber", replace(g, "\"radius\": 1", "\"radius\": 1e999"), "",
       "malformed JSON: the number 1e999 is beyond the range of a double"},
      {"FloatOverflow", replace(g, "[0, 3, 3]", "[0, 3e39, 3]"), "", "lights[0].position[1]: expected a finite number"},
      {"NaNLiteral", replace(g, "\"radius\": 1", "\"radius\": NaN"), "", "malformed JSON"},
      {"SppZeroInFile", replace(g, "\"spp\": 1", "\"spp\": 0"), "", "render.spp: spp must be at least 1"},
      {"SppZeroOnCommandLine", g, "--spp 0", "--spp: spp must be at least 1"},
      {"ResolutionTooLarge", replace(g, "\"width\": 16", "\"width\": 16385"), "", "film.width: must be in [1, 16384]"},
      {"ResolutionTooLargeOnCommandLine", g, "--height 20000", "--height: must be in [1, 16384]"},
      {"UnknownMaterial", replace(g, "\"material\": \"m\"}]", "\"material\": \"x\"}]"), "",
       "shapes[0].material: unknown material \"x\""},
      {"GridNeedsSquareSpp", g, "--sampler grid --spp 3", "needs a square spp"},
      {"TextureMissing", replace(g, "\"albedo\": [0.5, 0.5, 0.5]", "\"albedo\": {\"texture\": \"a.png\"}"), "",
       "materials.m.albedo.texture: image"},
      {"UnknownIntegrator", g, "--integrator photons", "unknown integrator \"photons\""},
      {"UnknownAccel", g, "--accel octree", "unknown accel \"octree\""},
      {"MaxDepthTooLarge", g, "--max-depth 65", "--max-depth: must be at most 64"},
      {"BadOutputExtension", g, "-o OUTDIR/out.nosuchformat", "no image writer"},
      {"UnknownDevice", g, "-o OUTDIR/out.png --device gpu", "--device gpu: expected cpu or cuda"},
      {"UnknownEffect", g, "-o OUTDIR/out.png --effects glow", "unknown effect \"glow\""},
      {"SamplesNeedAPartialFile", g, "-o OUTDIR/out.png --samples 0:1", "--samples writes a partial file"},
      {"SampleRangeBeyondSpp", g, "-o OUTDIR/out.partial --samples 0:2",
       "--samples 0:2: expected 0 <= A < B <= spp (1)"},
  };
}

}  // namespace

TEST_P(CliBadInput, ExitsWithCode2NamesTheKeyAndWritesNothing) {
  const BadInput& in = GetParam();
  const auto dir = test::temp_dir(std::string("cli-") + in.name);
  const auto scene = dir / "inline.json";
  if (!in.scene.empty()) std::ofstream(scene) << in.scene;
  // An existing output must survive a failed render untouched.
  const auto out = dir / "out.png";
  std::ofstream(out) << "previous";
  std::string args = in.args;
  const size_t at = args.find("OUTDIR");
  if (at != std::string::npos) args.replace(at, 6, dir.string());
  std::string output;
  const std::string output_arg = args.find("-o ") == std::string::npos ? " -o " + out.string() : "";
  const int code = test::run_tracer("render " + scene.string() + output_arg + " --quiet " + args, &output);
  EXPECT_EQ(code, 2) << output;
  EXPECT_NE(output.find("error: "), std::string::npos) << output;
  EXPECT_NE(output.find(in.expected), std::string::npos) << "expected \"" << in.expected << "\" in: " << output;
  if (in.args.empty() || in.args.rfind("--", 0) == 0) {
    EXPECT_NE(output.find(scene.string()), std::string::npos) << "the message must name the file: " << output;
  }
  std::stringstream kept;
  kept << std::ifstream(out).rdbuf();
  EXPECT_EQ(kept.str(), "previous");
  size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, in.scene.empty() ? 1u : 2u) << "no temporary or partial file may be left";
  std::filesystem::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(AllBadInputs, CliBadInput, ::testing::ValuesIn(bad_inputs()),
                         [](const auto& info) { return std::string(info.param.name); });

// `tracer --version` names the build: version, the commit of the source tree (as git
// says, when it can), the compiler, the CPU kernels compiled in and whether CUDA was built.
TEST(Cli, VersionNamesTheBuild) {
  std::string out;
  ASSERT_EQ(test::run_tracer("--version", &out), 0) << out;
  for (const char* line : {"tracer 0.", "\ncommit: ", "\ncompiler: ", "\nCPU kernels: x86-64/generic",
                           "\nthis CPU runs: x86-64", "\nCUDA renderer: "})
    EXPECT_NE(out.find(line), std::string::npos) << line << " missing:\n" << out;
  // The commit is one of the checkout's (the build's; HEAD may have moved on since), when git works here.
  if (test::run_command("git -C " + test::source_path("") + " rev-parse HEAD >/dev/null 2>&1") == 0) {
    const size_t at = out.find("commit: ") + 8;
    const std::string commit = out.substr(at, out.find_first_of("-\n", at) - at);
    EXPECT_EQ(commit.size(), 12u) << out;
    EXPECT_EQ(test::run_command("git -C " + test::source_path("") + " merge-base --is-ancestor " + commit + " HEAD"), 0)
        << "commit " << commit << " is not in this checkout's history";
  }
}

TEST(Cli, RenderWritesImageAndStats) {
  const auto dir = test::temp_dir("cli-render");
  std::ofstream(dir / "s.json") << kGoodScene;
  std::string output;
  ASSERT_EQ(test::run_tracer("render " + (dir / "s.json").string() + " -o " + (dir / "a.exr").string() + " --stats " +
                                 (dir / "stats.json").string(),
                             &output),
            0)
      << output;
  EXPECT_TRUE(std::filesystem::exists(dir / "a.exr"));
  const Json stats = Json::parse(std::ifstream(dir / "stats.json"));
  EXPECT_EQ(stats["rays"]["camera"], 16 * 12);
  EXPECT_GT(stats["rays"]["shadow"].get<int>(), 0);
  EXPECT_EQ(stats["nonfinite_samples"], 0);
  EXPECT_TRUE(stats["seconds"].contains("build"));
  EXPECT_NE(output.find("16x12, 1 spp"), std::string::npos) << output;
  std::filesystem::remove_all(dir);
}

// --stats names the structure --accel chose and counts its nodes or cells.
TEST(Cli, StatsNameEveryAccelerationStructure) {
  const auto dir = test::temp_dir("cli-accel-stats");
  std::ofstream(dir / "s.json") << kGoodScene;
  for (const std::string accel : {"bvh", "lbvh", "kdtree", "kdtree-median", "grid", "none"}) {
    std::string output;
    ASSERT_EQ(test::run_tracer("render " + (dir / "s.json").string() + " --quiet --accel " + accel + " -o " +
                                   (dir / "a.exr").string() + " --stats " + (dir / "stats.json").string(),
                               &output),
              0)
        << output;
    const Json stats = Json::parse(std::ifstream(dir / "stats.json"));
    EXPECT_EQ(stats["accel"]["kind"], accel);
    if (accel == "none" || accel == "grid") {
      EXPECT_EQ(stats["accel"]["nodes"], 0) << accel;
    } else {
      EXPECT_GT(stats["accel"]["nodes"].get<int>(), 0) << accel;
    }
    EXPECT_EQ(stats["accel"].contains("cells"), accel == "grid") << accel;
    if (accel == "grid") {
      EXPECT_GT(stats["accel"]["cells"].get<int>(), 0);
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(Cli, CompareExitCodes) {
  const auto dir = test::temp_dir("cli-compare");
  std::ofstream(dir / "s.json") << kGoodScene;
  const std::string s = (dir / "s.json").string();
  ASSERT_EQ(test::run_tracer("render " + s + " --quiet -o " + (dir / "a.exr").string()), 0);
  ASSERT_EQ(test::run_tracer("render " + s + " --quiet -o " + (dir / "b.exr").string()), 0);
  ASSERT_EQ(
      test::run_tracer("render " + s + " --quiet --seed 2 --spp 4 --sampler stochastic -o " + (dir / "c.exr").string()),
      0);
  std::string output;
  EXPECT_EQ(
      test::run_tracer("compare " + (dir / "a.exr").string() + " " + (dir / "b.exr").string() + " --fail 0", &output),
      0)
      << output;
  EXPECT_NE(output.find("PASS: bit-identical"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer("compare " + (dir / "a.exr").string() + " " + (dir / "c.exr").string() +
                                 " --fail 0 --diff " + (dir / "d.exr").string(),
                             &output),
            1)
      << output;
  EXPECT_NE(output.find("FAIL"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(dir / "d.exr"));
  EXPECT_EQ(
      test::run_tracer("compare " + (dir / "a.exr").string() + " " + (dir / "c.exr").string() + " --fail 10", &output),
      0)
      << output;
  EXPECT_EQ(test::run_tracer("compare " + (dir / "a.exr").string() + " " + (dir / "missing.exr").string(), &output), 2)
      << output;
  std::filesystem::remove_all(dir);
}

TEST(Cli, InfoReportsCountsAndFeatures) {
  std::string output;
  ASSERT_EQ(test::run_tracer("info " + test::source_path("scenes/cornell-box.json"), &output), 0) << output;
  EXPECT_NE(output.find("spheres 2"), std::string::npos) << output;
  EXPECT_NE(output.find("dielectric"), std::string::npos) << output;
  EXPECT_NE(output.find("bvh"), std::string::npos) << output;
}
