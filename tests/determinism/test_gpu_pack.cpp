// The GPU pack without a GPU (docs/cuda.md): the self-contained runner, from the pack's
// scene bundles alone, reproduces every golden's manifest hash and every parity case's CPU
// answers on the CPU; it links nothing but libc, libm and the loader; malformed bundles
// are refused with exit 2 and nothing written; and a wrong hash fails, so the check has power.
#include <gtest/gtest.h>

#include <fstream>
#include <iomanip>
#include <sstream>

#include "accel/lbvh_builder.h"
#include "golden/golden_manifest.h"
#include "image/image_io.h"
#include "image/pixel_hash.h"
#include "kernel/accel/trace_variants.h"
#include "parity/parallel_for.h"
#include "parity/parity_inputs.h"
#include "sanitizer.h"
#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

std::string runner() { return TRACER_GPU_BINARY; }

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void spill(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

// The pack the CTest fixture gpu-pack.write made (tests/CMakeLists.txt).
fs::path pack() { return TRACER_GPU_PACK; }

// Agreement, not correctness: it compares with the golden hashes, so once the goldens are
// regenerated it shows only that the runner's bundles agree with the render the update made; it is no
// evidence that the image is right (docs/mutation.md).
TEST(GpuPack, RunnerOnTheCpuReproducesEveryGoldenHashAndParityAnswer) {
  std::string out;
  ASSERT_EQ(test::run_command((pack() / "run.sh").string() + " --device cpu", &out), 0) << out;
  const GoldenManifest manifest = read_manifest(TRACER_SOURCE_DIR);
  for (const GoldenEntry& e : manifest.entries) {
    std::ostringstream row;
    row << std::left << std::setw(10) << (e.image == GoldenImage::SampleMap ? "sample-map" : "golden") << " " << e.name;
    for (const char* schedule : {" ", "@stream ", "@sorted "}) {  // the stream schedule's rows: the same hash
      const size_t at = out.find(row.str() + schedule);
      ASSERT_NE(at, std::string::npos) << e.name << schedule << " has no row:\n" << out;
      EXPECT_NE(out.substr(at, 60).find("PASS"), std::string::npos) << out.substr(at, 200);
    }
  }
  // Each trace variant of the GPU's stream schedule renders a golden in the pack: a golden's own
  // stream row, or one with another structure (NAME@ACCEL@stream). The runner names the variant
  // a stream row runs on the GPU.
  for (const TraceVariant& v : kTraceVariants)
    EXPECT_NE(out.find(std::string(", trace ") + v.name + "\n"), std::string::npos)
        << v.name << " renders no golden in the pack:\n"
        << out;
  for (const char* c : {"math-sin", "math-pow", "philox", "shapes", "trace-mesh-bvh", "trace-mesh-lbvh",
                        "trace-mesh-kdtree", "trace-mesh-grid", "trace-mesh-none", "adaptive-decision", "lbvh-build-1m",
                        "sample-cornell-box", "stream-cornell-box", "stream-cornell-box-path"})
    EXPECT_NE(out.find(std::string(c) + " "), std::string::npos) << c << " missing:\n" << out;
  EXPECT_EQ(out.find("FAIL"), std::string::npos) << out;
}

TEST(GpuPack, StaysWellUnderTheDeviceCallLimit) {
#if TRACER_UNDER_ADDRESS_SANITIZER
  GTEST_SKIP() << "an AddressSanitizer build's runner is twice the size (16 MB); the pack carried to a GPU is the "
                  "default build's";
#endif
  uint64_t bytes = 0;
  for (const auto& e : fs::recursive_directory_iterator(pack()))
    if (e.is_regular_file()) bytes += e.file_size();
  // A device call carries the checkout's tracked files and the pack, at most 64 MiB together.
  // The runner (17.6 MB, most of it the kernels' compressed fatbin: sm_80 and sm_90 code and PTX) and
  // the bench's two bundles of the 99k-triangle sphere (8 MB each; the rays table's copy is made
  // by the runner) are most of the pack; the goldens' bundles add 5 MB. At least 4 MiB stay free
  // for what the next goldens add.
  std::string tracked;
  if (test::run_command(
          "cd " + test::source_path("") + " && git ls-files -z >/dev/null && git ls-files -z | xargs -0 cat | wc -c",
          &tracked) != 0)
    GTEST_SKIP() << "not a git checkout: the tracked files' size is not known";
  const uint64_t tree = std::stoull(tracked);
  EXPECT_LT(bytes + tree, 60u << 20) << "the pack (" << bytes << " bytes) and the tracked files (" << tree
                                     << ") are what a device call carries, at most 64 MiB";
}

TEST(GpuPack, AWrongGoldenHashFailsItsRowAndThePack) {
  const fs::path dir = test::temp_dir("gpu-pack-mutated");
  fs::copy_file(pack() / "tracer-gpu", dir / "tracer-gpu");
  fs::copy_file(pack() / "run.sh", dir / "run.sh");
  fs::create_directories(dir / "bundles");
  std::string list, line;
  std::istringstream rows(slurp(pack() / "pack.tsv"));
  while (std::getline(rows, line)) {
    if (line.rfind("golden refraction ", 0) != 0 && line.rfind("golden shadows ", 0) != 0) continue;
    const std::string file = line.substr(line.find("bundles/"), line.find(".bundle") + 7 - line.find("bundles/"));
    fs::copy_file(pack() / file, dir / file);
    if (line.rfind("golden refraction ", 0) == 0) {  // one hex digit of the expected hash changed
      const size_t at = line.find("sha1:") + 5;
      line[at] = line[at] == '0' ? '1' : '0';
    }
    list += line + "\n";
  }
  spill(dir / "pack.tsv", list);
  std::string out;
  EXPECT_EQ(test::run_command((dir / "run.sh").string() + " --device cpu", &out), 1) << out;
  const size_t refraction = out.find("golden     refraction "), shadows = out.find("golden     shadows ");
  ASSERT_NE(refraction, std::string::npos) << out;
  ASSERT_NE(shadows, std::string::npos) << out;
  EXPECT_NE(out.substr(refraction, 60).find("FAIL"), std::string::npos) << out;
  EXPECT_NE(out.substr(shadows, 60).find("PASS"), std::string::npos) << out;
  EXPECT_NE(out.find("1 of 2 passed"), std::string::npos) << out;
  fs::remove_all(dir);
}

// bench.tsv lists the tables of `tracer bench device`; the runner times its rows.
TEST(GpuPack, BenchRowsCoverTheDeviceTablesAndTheRunnerTimesThem) {
  const std::string list = slurp(pack() / "bench.tsv");
  for (const char* row : {"main cornell-box-1spp-center ", "main cornell-box-4spp-grid ", "effects none-1spp-center ",
                          "effects all-2spp-stochastic ", "resolution 1920x1080-4spp-grid ", "mesh sphere-",
                          "schedule cornell-box-path-16spp-megakernel ",
                          "schedule cornell-box-path-16spp-stream:4194304 ", "schedule sphere-4spp-grid-stream:262144 ",
                          "schedule cornell-box-path-16spp-stream:4194304:sorted ",
                          "rays sphere-", "rays terrain-1m bench/rays-terrain-1m.bundle mesh:terrain:1000000"})
    EXPECT_NE(list.find(row), std::string::npos) << row << " missing:\n" << list;
  const fs::path dir = test::temp_dir("gpu-pack-bench");
  fs::create_directories(dir / "bench");
  std::string main_rows, line;
  std::istringstream rows(list);
  while (std::getline(rows, line))
    if (line.rfind("main ", 0) == 0) {
      const std::string file = line.substr(line.rfind(' ') + 1);
      fs::copy_file(pack() / file, dir / file);
      main_rows += line + "\n";
    }
  spill(dir / "bench.tsv", main_rows);
  std::string out;
  ASSERT_EQ(test::run_command(runner() + " bench " + dir.string() + " --device cpu", &out), 0) << out;
  EXPECT_NE(out.find("main       cornell-box-4spp-grid"), std::string::npos) << out;
  fs::remove_all(dir);
}

// The rays table traces bench rays' three ray sets through bvh's two trees; on the CPU both
// must give the same hits, and a bundle of another structure is refused.
TEST(GpuPack, TheRaysTableTracesBothTreesWithTheSameHits) {
  const fs::path dir = test::temp_dir("gpu-pack-rays");
  fs::create_directories(dir / "bundles");
  for (const char* bundle : {"gltf-cornell-box.bundle", "ior-one-path@kdtree.bundle"})
    fs::copy_file(pack() / "bundles" / bundle, dir / "bundles" / bundle);
  spill(dir / "bench.tsv", "rays gltf-cornell-box bundles/gltf-cornell-box.bundle\n");
  std::string out;
  ASSERT_EQ(test::run_command(runner() + " bench " + dir.string() + " --device cpu", &out), 0) << out;
  EXPECT_NE(out.find("rays       gltf-cornell-box cpu bvh8"), std::string::npos) << out;
  EXPECT_NE(out.find("rays       gltf-cornell-box cpu bvh "), std::string::npos) << out;
  EXPECT_EQ(out.find("DIFFERENT"), std::string::npos) << out;
  spill(dir / "bench.tsv", "rays ior-one-path bundles/ior-one-path@kdtree.bundle\n");
  EXPECT_EQ(test::run_command(runner() + " bench " + dir.string() + " --device cpu", &out), 2) << out;
  EXPECT_NE(out.find("ior-one-path: the rays table traces bvh's two trees"), std::string::npos) << out;
  // A mesh the runner generates in a bundle's view (the pack's 10^6-triangle terrain), smaller here.
  fs::create_directories(dir / "bench");
  fs::copy_file(pack() / "bench/rays-terrain-1m.bundle", dir / "bench/rays-terrain-1m.bundle");
  spill(dir / "bench.tsv", "rays terrain bench/rays-terrain-1m.bundle mesh:terrain:20000\n");
  ASSERT_EQ(test::run_command(runner() + " bench " + dir.string() + " --device cpu", &out), 0) << out;
  EXPECT_NE(out.find("rays       terrain cpu bvh "), std::string::npos) << out;
  EXPECT_EQ(out.find("DIFFERENT"), std::string::npos) << out;
  for (const char* spec : {"mesh:terrain:0", "mesh:terrain:99999999999", "mesh:terrain", "mesh:nope:100"}) {
    spill(dir / "bench.tsv", std::string("rays terrain bench/rays-terrain-1m.bundle ") + spec + "\n");
    EXPECT_EQ(test::run_command(runner() + " bench " + dir.string() + " --device cpu", &out), 2) << spec << out;
    const std::string why = std::string(spec) == "mesh:nope:100"  ? "generate nope: unknown mesh kind"
                            : std::string(spec) == "mesh:terrain" ? "mesh:terrain: expected mesh:KIND:TRIANGLES"
                                                                  : ": expected a whole number from 1 to 16777216";
    EXPECT_NE(out.find("bench.tsv: terrain: "), std::string::npos) << spec << out;
    EXPECT_NE(out.find(why), std::string::npos) << spec << out;
  }
  fs::remove_all(dir);
}

TEST(GpuPack, RefusesADirectoryThatIsNotEmptyAndLeavesIt) {
  std::string out;
  ASSERT_TRUE(fs::exists(pack() / "pack.tsv"));
  EXPECT_EQ(test::run_tracer("gpu-pack " + pack().string() + " --root " + TRACER_SOURCE_DIR, &out), 2) << out;
  EXPECT_NE(out.find("not an empty directory"), std::string::npos) << out;
  EXPECT_TRUE(fs::exists(pack() / "pack.tsv"));
  // With a trailing slash, the same directory (it was read as a parent that does not exist).
  EXPECT_EQ(test::run_tracer("gpu-pack " + pack().string() + "/ --root " + TRACER_SOURCE_DIR, &out), 2) << out;
  EXPECT_NE(out.find("not an empty directory"), std::string::npos) << out;
  EXPECT_EQ(test::run_tracer("gpu-pack /nonexistent-tracer-dir/pack/ --root " + std::string(TRACER_SOURCE_DIR), &out),
            2)
      << out;
  EXPECT_NE(out.find("parent directory /nonexistent-tracer-dir does not exist"), std::string::npos) << out;
  // A link to an empty directory is refused before the work (the whole pack was built, then the rename failed).
  const fs::path dir = test::temp_dir("gpu-pack-link");
  fs::create_directories(dir / "empty");
  fs::create_symlink(dir / "empty", dir / "link");
  EXPECT_EQ(test::run_tracer("gpu-pack " + (dir / "link").string() + " --root " + TRACER_SOURCE_DIR, &out), 2) << out;
  EXPECT_NE(out.find("a symbolic link"), std::string::npos) << out;
  EXPECT_TRUE(fs::is_empty(dir / "empty"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);  // no staging left
  fs::remove_all(dir);
}

TEST(GpuRunner, LinksOnlyLibcLibmAndTheLoader) {
#if TRACER_UNDER_ADDRESS_SANITIZER
  GTEST_SKIP() << "a sanitizer build (cmake --preset sanitize) links its runtime into tracer-gpu";
#endif
  std::string out;
  ASSERT_EQ(test::run_command("ldd " + runner(), &out), 0) << out;
  std::istringstream lines(out);
  int libraries = 0;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string name;
    words >> name;
    if (name.empty()) continue;
    ++libraries;
    const bool allowed = name == "linux-vdso.so.1" || name == "libc.so.6" || name == "libm.so.6" ||
                         name.find("ld-linux") != std::string::npos;
    EXPECT_TRUE(allowed) << "tracer-gpu needs " << line;
  }
  EXPECT_GE(libraries, 2) << out;
}

// The LBVH steps of kernel/accel/lbvh.h give the same nodes and leaf order under the tracer's
// OpenMP loops and under the runner's std::threads at any count (the GPU grid is the third).
TEST(LbvhBuild, OpenMpAndStdThreadsGiveTheSameTree) {
  const LbvhInput in = parity::lbvh_inputs(3, 100000);
  std::vector<BuildItem> items;
  for (size_t i = 0; i < in.boxes.size(); ++i) {
    Bounds b;
    b.grow(in.boxes[i].lo);
    b.grow(in.boxes[i].hi);
    items.push_back({b, in.centroids[i], in.ids[i]});
  }
  const std::vector<BvhNode> openmp = build_lbvh(items);
  for (unsigned threads : {1u, 2u, 7u}) {
    const LbvhTree tree = build_lbvh_tree(in, [&](size_t n, const auto& fn) { parallel_for(n, threads, fn, 16); });
    ASSERT_EQ(tree.nodes.size(), openmp.size());
    EXPECT_EQ(std::memcmp(tree.nodes.data(), openmp.data(), openmp.size() * sizeof(BvhNode)), 0)
        << threads << " threads";
    ASSERT_EQ(tree.order.size(), items.size());
    for (size_t k = 0; k < items.size(); ++k) ASSERT_EQ(in.ids[tree.order[k]], items[k].id) << "leaf " << k;
  }
}

// A bundle of the refraction scene, rendered by the runner; then damaged copies of it.
class BundleInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::temp_dir("bundle-input");
    bundle_ = (dir_ / "refraction.bundle").string();
    std::string out;
    ASSERT_EQ(test::run_tracer("bundle " + test::source_path("scenes/features/refraction.json") +
                                   " --width 32 --height 24 -o " + bundle_,
                               &out),
              0)
        << out;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // The runner on `input` must exit 2 naming it and leave the film output as it was.
  void expect_refused(const std::string& input, const std::string& message) {
    const fs::path film = dir_ / "out.film";
    spill(film, "earlier film");
    std::string out;
    EXPECT_EQ(test::run_command(runner() + " render " + input + " --device cpu -o " + film.string(), &out), 2) << out;
    EXPECT_NE(out.find("error: " + input), std::string::npos) << out;
    EXPECT_NE(out.find(message), std::string::npos) << out;
    EXPECT_EQ(slurp(film), "earlier film") << "a failed run must leave earlier files as they were";
  }
  fs::path dir_;
  std::string bundle_;
};

TEST_F(BundleInput, TheRunnerRendersItAndAWrongExpectedHashFails) {
  std::string out;
  const std::string film = (dir_ / "a.film").string();
  ASSERT_EQ(test::run_command(runner() + " render " + bundle_ + " --device cpu -o " + film, &out), 0) << out;
  EXPECT_EQ(out.rfind("sha1:", 0), 0u) << out;
  EXPECT_TRUE(fs::exists(film));
  const std::string hash = out.substr(0, out.find(' '));
  EXPECT_EQ(test::run_command(runner() + " render " + bundle_ + " --device cpu --expect " + hash, &out), 0) << out;
  const std::string wrong = "sha1:" + std::string(40, '0');
  EXPECT_EQ(test::run_command(runner() + " render " + bundle_ + " --device cpu --expect " + wrong, &out), 1) << out;
  EXPECT_NE(out.find("FAIL"), std::string::npos) << out;
  // A hash no render can have is refused before the render.
  EXPECT_EQ(test::run_command(runner() + " render " + bundle_ + " --device cpu --expect sha1:0", &out), 2) << out;
  EXPECT_NE(out.find("--expect sha1:0: expected sha1: and 40 hexadecimal digits"), std::string::npos) << out;
}

// --schedule stream renders the megakernel's film at any width; bad schedules exit 2 and
// leave the film output as it was, in a pack row too.
TEST_F(BundleInput, TheRunnerStreamsTheMegakernelsFilmAndRefusesBadSchedules) {
  std::string out;
  ASSERT_EQ(test::run_command(runner() + " render " + bundle_ + " --device cpu", &out), 0) << out;
  const std::string hash = out.substr(0, out.find(' '));
  for (const char* width : {"7", "768", "16777216"})
    EXPECT_EQ(test::run_command(runner() + " render " + bundle_ + " --device cpu --schedule stream --stream-width " +
                                    width + " --expect " + hash,
                                &out),
              0)
        << width << ": " << out;
  const fs::path film = dir_ / "out.film";
  for (const std::string bad :
       {"--schedule streams", "--schedule", "--stream-width 0", "--stream-width 16777217", "--stream-width 1e3"}) {
    spill(film, "earlier film");
    EXPECT_EQ(
        test::run_command(runner() + " render " + bundle_ + " --device cpu " + bad + " -o " + film.string(), &out), 2)
        << bad << ": " << out;
    EXPECT_NE(out.find("error: --s"), std::string::npos) << bad << ": " << out;
    EXPECT_EQ(slurp(film), "earlier film") << bad;
  }
  fs::copy_file(bundle_, dir_ / "b.bundle");
  spill(dir_ / "pack.tsv", "golden b b.bundle " + hash + " stream:0\n");
  EXPECT_EQ(test::run_command(runner() + " pack " + dir_.string() + " --device cpu", &out), 1) << out;
  EXPECT_NE(out.find("pack.tsv: b: --stream-width 0: expected a whole number"), std::string::npos) << out;
}

// An adaptive bundle (8 spp, below the default min_spp of 16, which the render takes as
// min(min_spp, spp)): the runner's image and sample map hash as the tracer's own render.
TEST_F(BundleInput, TheRunnerRendersAnAdaptiveBundleAsTheTracerDoes) {
  const std::string scene = test::source_path("scenes/cornell-box-path.json"),
                    options = " --width 32 --height 24 --spp 8 --noise-threshold 0.3 --sampler sobol",
                    bundle = (dir_ / "adaptive.bundle").string(), image = (dir_ / "adaptive.exr").string(),
                    map = (dir_ / "map.exr").string();
  std::string out;
  ASSERT_EQ(test::run_tracer("bundle " + scene + options + " -o " + bundle, &out), 0) << out;
  ASSERT_EQ(test::run_tracer("render " + scene + options + " --quiet -o " + image + " --sample-map " + map, &out), 0)
      << out;
  ASSERT_EQ(test::run_command(runner() + " render " + bundle + " --device cpu", &out), 0) << out;
  EXPECT_NE(out.find(pixel_hash(read_image(map)) + " sample map"), std::string::npos) << out;
  EXPECT_NE(out.find(pixel_hash(read_image(image)) + " " + bundle), std::string::npos) << out;
  EXPECT_EQ(test::run_command(runner() + " render " + bundle + " --device cpu -o " + (dir_ / "a.film").string(), &out),
            2)
      << out;
  EXPECT_NE(out.find("is an adaptive render"), std::string::npos) << out;
  EXPECT_EQ(
      test::run_tracer("bundle " + scene + options + " --samples 0:4 -o " + (dir_ / "part.bundle").string(), &out), 2)
      << out;
  EXPECT_NE(out.find("cannot be split into sample ranges"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir_ / "part.bundle"));
}

TEST_F(BundleInput, TruncatedCorruptedOrForeignFilesAreRefused) {
  const std::string bytes = slurp(bundle_);
  const fs::path truncated = dir_ / "truncated.bundle", flipped = dir_ / "flipped.bundle",
                 empty = dir_ / "empty.bundle", foreign = dir_ / "scene.json";
  spill(truncated, bytes.substr(0, bytes.size() / 2));
  std::string f = bytes;
  f[f.size() / 2] ^= 0x10;
  spill(flipped, f);
  spill(empty, "");
  fs::copy_file(test::source_path("scenes/features/refraction.json"), foreign);
  expect_refused(truncated.string(), "checksum does not match");
  expect_refused(flipped.string(), "checksum does not match");
  expect_refused(empty.string(), "not a tracer bundle");
  expect_refused(foreign.string(), "not a tracer bundle");
  expect_refused((dir_ / "missing.bundle").string(), "cannot open bundle");
  expect_refused(dir_.string(), "not a regular file");
  expect_refused("/dev/zero", "not a regular file");
}

TEST_F(BundleInput, AParityCaseIsNotASceneBundle) {
  std::string out;
  ASSERT_EQ(test::run_command(runner() + " parity " + bundle_ + " --device cpu", &out), 2) << out;
  EXPECT_NE(out.find("a scene bundle; expected a parity bundle"), std::string::npos) << out;
}

TEST_F(BundleInput, TracerBundleRefusesBadArgumentsAndWritesNothing) {
  std::string out;
  const std::string scene = test::source_path("scenes/features/refraction.json");
  EXPECT_EQ(test::run_tracer("bundle " + scene + " -o " + (dir_ / "x.exr").string(), &out), 2) << out;
  EXPECT_NE(out.find("NAME.bundle"), std::string::npos) << out;
  EXPECT_EQ(test::run_tracer("bundle " + scene + " --spp 4 --samples 3:9 -o " + (dir_ / "y.bundle").string(), &out), 2)
      << out;
  EXPECT_FALSE(fs::exists(dir_ / "y.bundle"));
  EXPECT_EQ(test::run_tracer("bundle " + (dir_ / "none.json").string() + " -o " + (dir_ / "z.bundle").string(), &out),
            2)
      << out;
  EXPECT_FALSE(fs::exists(dir_ / "z.bundle"));
}

}  // namespace
}  // namespace tracer
