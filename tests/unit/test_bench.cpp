// The speed/accuracy benchmarks produce what they promise: a converge table with its CSV
// and plot, a trade table with a row per knob setting, and clear errors for bad options.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "image/image_io.h"
#include "test_util.h"

namespace tracer {
namespace {

TEST(Bench, ConvergeWritesTableCsvAndPlot) {
  const auto dir = test::temp_dir("bench-converge");
  const std::string csv = (dir / "c.csv").string(), plot = (dir / "c.png").string();
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);  // the reference goes beside the binary, not here
  std::string output;
  ASSERT_EQ(test::run_tracer("bench converge " + test::source_path("scenes/cornell-box-path.json") +
                                 " --width 16 --height 12 --spp 1,4 --ref-spp 16 --nee both --threads 1 --csv " + csv +
                                 " --plot " + plot,
                             &output),
            0)
      << output;
  EXPECT_NE(output.find("NEE+MIS reaches the plain estimator's RMSE"), std::string::npos) << output;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "series,spp,seconds,rmse,display_rmse,rel_mse");
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    EXPECT_TRUE(line.rfind("NEE+MIS,", 0) == 0 || line.rfind("plain,", 0) == 0) << line;
  }
  EXPECT_EQ(rows, 4);
  EXPECT_FALSE(std::filesystem::exists(dir / "cornell-box-path-converge-ref.exr"));
  EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(TRACER_BINARY).parent_path() / "bench-refs" /
                                      "cornell-box-path-converge-ref.exr"));
  std::filesystem::current_path(cwd);
  const Image png = read_image(plot);
  EXPECT_EQ(png.width, 800u);
  EXPECT_EQ(png.height, 560u);
  EXPECT_EQ(
      test::run_tracer("bench converge " + test::source_path("scenes/cornell-box-path.json") + " --spp 1,x", &output),
      2);
  EXPECT_NE(output.find("--spp 1,x: expected a comma-separated list"), std::string::npos) << output;
  std::filesystem::remove_all(dir);
}

// bench path --sampler: every scene renders with it (each row names the sampler its scene ran
// with); a sampler that is not one exits 2 naming the flag.
TEST(Bench, PathRendersEverySceneWithTheSamplerGiven) {
  const std::string scene = test::source_path("scenes/cornell-box-path.json");  // its own: stochastic
  std::string output;
  ASSERT_EQ(test::run_tracer("bench path " + scene + " --size 8 --spp 1 --repeats 1 --threads 1", &output), 0)
      << output;
  EXPECT_NE(output.find("cornell-box-path.json (stochastic)"), std::string::npos) << output;
  ASSERT_EQ(
      test::run_tracer("bench path " + scene + " --sampler sobol --size 8 --spp 1 --repeats 1 --threads 1", &output), 0)
      << output;
  EXPECT_NE(output.find("sampler sobol in every scene"), std::string::npos) << output;
  EXPECT_NE(output.find("cornell-box-path.json (sobol)"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer("bench path " + scene + " --sampler sobel --size 8 --spp 1", &output), 2);
  EXPECT_NE(output.find("--sampler: unknown sampler \"sobel\""), std::string::npos) << output;
}

// --configs: a series per configuration of render options, each against the first, its label
// quoted in the CSV where it holds a comma; a configuration that is no such list exits 2 first.
TEST(Bench, ConvergeComparesConfigurations) {
  const auto dir = test::temp_dir("bench-converge-configs");
  const std::string csv = (dir / "c.csv").string(), plot = (dir / "c.png").string();
  const std::string scene = test::source_path("scenes/cornell-box-path.json");
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  std::string output;
  ASSERT_EQ(test::run_tracer("bench converge " + scene + " --width 16 --height 12 --spp 1,4 --ref-spp 16 --threads 1" +
                                 " --configs 'rr_depth=3;rr_depth=65,nee=off' --csv " + csv + " --plot " + plot,
                             &output),
            0)
      << output;
  EXPECT_NE(output.find("rr_depth=65,nee=off against rr_depth=3, RMSE at equal spp: 1 spp"), std::string::npos)
      << output;
  EXPECT_NE(output.find("time to equal RMSE"), std::string::npos) << output;
  std::ifstream in(csv);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_NE(text.str().find("\nrr_depth=3,4,"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("\n\"rr_depth=65,nee=off\",4,"), std::string::npos) << text.str();
  std::filesystem::current_path(cwd);
  const struct {
    const char *configs, *message;
  } bad[] = {{"rr_depth=3", "--configs: give two or more configurations"},
             {"rr_depth=3;spp=4", "--configs \"spp=4\": spp is the command's own (--spp)"},
             {"rr_depth=3;bogus=1", "--configs \"bogus=1\": unknown render option \"bogus\""},
             {"rr_depth=3;nee", "--configs \"nee\": expected KEY=VALUE, not \"nee\""},
             {"rr_depth=3;;nee=off", "--configs \"rr_depth=3;;nee=off\": an empty configuration"},
             {"rr_depth=3;rr_depth=x", "--configs \"rr_depth=x\": --rr-depth \"x\""}};
  for (const auto& b : bad) {
    std::filesystem::remove(csv);
    EXPECT_EQ(test::run_tracer(
                  "bench converge " + scene + " --spp 4 --configs '" + b.configs + "' --csv " + csv + " --plot " + plot,
                  &output),
              2)
        << b.configs << ": " << output;
    EXPECT_NE(output.find(b.message), std::string::npos) << b.configs << ": " << output;
    EXPECT_FALSE(std::filesystem::exists(csv)) << b.configs;
  }
  // A configuration that cannot take one of the smaller spp is refused before the reference
  // renders, naming it (checked at the largest spp alone, it was refused after rows were
  // printed, blaming --min-spp, a flag not given).
  EXPECT_EQ(test::run_tracer("bench converge " + scene +
                                 " --width 8 --height 6 --spp 1,4 --configs 'rr_depth=3;noise_threshold=0.1,min_spp=4'"
                                 " --csv " +
                                 csv + " --plot " + plot,
                             &output),
            2)
      << output;
  EXPECT_NE(output.find("--configs \"noise_threshold=0.1,min_spp=4\".min_spp (the options of"), std::string::npos)
      << output;
  EXPECT_NE(output.find("(at --spp 1)"), std::string::npos) << output;
  EXPECT_EQ(output.find("RMSE"), std::string::npos) << "no row before the refusal: " << output;
  EXPECT_EQ(output.find("command line --min-spp"), std::string::npos) << output;
  std::filesystem::remove_all(dir);
}

TEST(Bench, TradeHasARowPerKnobSetting) {
  const auto dir = test::temp_dir("bench-trade");
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  std::string output;
  ASSERT_EQ(test::run_tracer("bench trade " + test::source_path("scenes/cornell-box-path.json") +
                                 " --width 12 --height 8 --spp 4 --ref-spp 8 --threads 1",
                             &output),
            0)
      << output;
  for (const char* row :
       {"nee          off", "sampler      stratified", "fresnel      exact", "rr_depth     off", "max_depth    16"})
    EXPECT_NE(output.find(row), std::string::npos) << row << " in " << output;
  EXPECT_EQ(output.find("sky_sampling"), std::string::npos) << "no cube-map sky, no sky knob: " << output;
  ASSERT_EQ(test::run_tracer("bench trade " + test::source_path("scenes/features/sun-sky.json") +
                                 " --width 12 --height 8 --spp 4 --ref-spp 8 --threads 1",
                             &output),
            0)
      << output;
  EXPECT_NE(output.find("sky_sampling off"), std::string::npos) << output;
  // A scene of its own with the stratified sampler keeps every row's spp square.
  ASSERT_EQ(test::run_tracer("bench trade " + test::source_path("scenes/features/ior-one.json") +
                                 " --width 12 --height 8 --spp 4 --ref-spp 16 --threads 1",
                             &output),
            0)
      << output;
  EXPECT_NE(output.find("fresnel      schlick"), std::string::npos) << output;
  std::filesystem::current_path(cwd);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(test::run_tracer("bench trade " + test::source_path("scenes/features/shadows.json"), &output), 2);
  EXPECT_NE(output.find("measures the path integrator"), std::string::npos) << output;
  // An adaptive scene (target_error alone) cannot take the stratified sampler's knob: refused
  // before any render, naming the knob and the sampler (it rendered 36 images first, then
  // blamed render.noise_threshold, which the scene does not set).
  std::string text = test::read_file(test::source_path("scenes/cornell-box-path.json"));
  text.replace(text.find("\"render\": {"), 11, "\"render\": {\"target_error\": 0.05, ");
  const auto adaptive = test::temp_dir("bench-trade-adaptive") / "adaptive.json";
  std::ofstream(adaptive) << text;
  EXPECT_EQ(test::run_tracer("bench trade " + adaptive.string() + " --width 8 --height 6 --spp 4", &output), 2)
      << output;
  EXPECT_NE(output.find("bench trade: knob sampler stratified: "), std::string::npos) << output;
  EXPECT_NE(output.find("--sampler: adaptive sampling needs a sampler"), std::string::npos) << output;
  EXPECT_EQ(output.find("noise_threshold"), std::string::npos) << output;
  EXPECT_EQ(output.find("RMSE"), std::string::npos) << "no row before the refusal: " << output;
  std::filesystem::remove_all(adaptive.parent_path());
}

// One repeat each: the test is the hits' checksums, not the times.
TEST(Bench, RaysGivesEveryStructureTheSameHits) {
  const auto dir = test::temp_dir("bench-rays");
  const std::string obj = (dir / "cubes.obj").string();
  std::string output;
  ASSERT_EQ(test::run_tracer("generate cubes --triangles 600 -o " + obj, &output), 0) << output;
  ASSERT_EQ(test::run_tracer("bench rays " + obj +
                                 " --rays 4096 --threads 1 --repeats 1 --accel bvh,lbvh,kdtree,kdtree-median,grid,none",
                             &output),
            0)
      << output;
  for (const char* accel : {"bvh ", "lbvh ", "kdtree ", "kdtree-median ", "grid ", "none "}) {
    const size_t row = output.find(std::string("\n") + accel);
    ASSERT_NE(row, std::string::npos) << accel << " in " << output;
    EXPECT_NE(output.substr(row, output.find('\n', row + 1) - row).find(" same"), std::string::npos) << accel;
  }
  // Where Embree is built in, its row comes with the ratios of its medians and the paired ones.
  if (output.find("\nembree 3 ") != std::string::npos) {
    EXPECT_NE(output.find("\nbvh / embree "), std::string::npos) << output;
    EXPECT_NE(output.find("\npaired ratio "), std::string::npos) << output;
  }
  EXPECT_EQ(test::run_tracer("generate blob -o " + obj, &output), 2);
  EXPECT_NE(output.find("unknown mesh kind"), std::string::npos) << output;
  // A scene of spheres gets every structure's row and no Embree row (it printed the rows, then exited 2).
  const std::string spheres = (dir / "spheres.json").string();
  std::ofstream(spheres) << R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 5], "to": [0, 0, 0], "vfov": 40},
    "film": {"width": 8, "height": 8}, "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "shapes": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
  ASSERT_EQ(
      test::run_tracer("bench rays " + spheres + " --rays 1024 --threads 1 --accel bvh,grid --repeats 1", &output), 0)
      << output;
  EXPECT_NE(output.find("\ngrid "), std::string::npos) << output;
  EXPECT_EQ(output.find("\nembree 3 "), std::string::npos) << output;
  std::filesystem::remove_all(dir);
}

// With --device cuda each structure gets a GPU row whose hits must equal the CPU's; on a
// machine or build without a GPU the command says so before any work, exit 2.
TEST(Bench, RaysOnTheGpuMatchTheCpuOrSayWhyNot) {
  const auto dir = test::temp_dir("bench-rays-cuda");
  const std::string obj = (dir / "cubes.obj").string();
  std::string output;
  ASSERT_EQ(test::run_tracer("generate cubes --triangles 600 -o " + obj, &output), 0) << output;
  const int code =
      test::run_tracer("bench rays " + obj + " --rays 4096 --threads 1 --accel bvh,grid --device cuda", &output);
  if (code == 0) {
    for (const char* row : {"\nbvh cuda ", "\nbvh cuda sorted ", "\nbvh nodes cuda ", "\nbvh8 cuda ", "\ngrid cuda "}) {
      const size_t at = output.find(row);
      ASSERT_NE(at, std::string::npos) << row << " in " << output;
      EXPECT_NE(output.substr(at, output.find('\n', at + 1) - at).find(" same (trace "), std::string::npos) << output;
    }
  } else {
    EXPECT_EQ(code, 2) << output;
    EXPECT_NE(output.find("CUDA"), std::string::npos) << output;
    EXPECT_EQ(output.find("\nbvh "), std::string::npos) << "a row before the refusal:\n" << output;
  }
  EXPECT_EQ(test::run_tracer("bench rays " + obj + " --device metal", &output), 2);
  std::filesystem::remove_all(dir);
}

TEST(Bench, GeneratedMeshesAreDeterministic) {
  const auto dir = test::temp_dir("generate");
  for (const char* kind : {"terrain", "sphere", "boxes", "cubes", "mixed"}) {
    const std::string a = (dir / "a.obj").string(), b = (dir / "b.obj").string();
    ASSERT_EQ(test::run_tracer(std::string("generate ") + kind + " --triangles 3000 -o " + a), 0);
    ASSERT_EQ(test::run_tracer(std::string("generate ") + kind + " --triangles 3000 -o " + b), 0);
    std::stringstream sa, sb;
    sa << std::ifstream(a).rdbuf();
    sb << std::ifstream(b).rdbuf();
    EXPECT_EQ(sa.str(), sb.str()) << kind;
    EXPECT_GT(sa.str().size(), 100u) << kind;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tracer
