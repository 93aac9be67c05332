// Hostile input through the CLI, outputs and the GPU runner: a scene bundle is held to a
// scene's limits, and no command's output (the runner's film included) may name one of its
// inputs or a device (tests/unit/test_hostile_input.cpp has the rest).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <functional>

#include "bundle/scene_bundle.h"
#include "hostile_input.h"
#include "image/image_io.h"
#include "sanitizer.h"
#include "scene/scene_loader.h"
#include "test_util.h"

namespace tracer {
namespace {

// A scene bundle describes a render as a scene does, and is held to the same limits and the same
// check of its settings (options/settings_check.h): tracer-gpu rendered bundles asking for
// max_depth 1000, a 20000-pixel film or 2^37 samples, and crashed or drew black on derived ones.
TEST_F(HostileInput, ABundleIsHeldToTheLimitsOfAScene) {
  const std::string scene_path = scene_file(scene_text(R"("spp": 1)"));
  const Scene scene = load_scene(scene_path);
  const std::string bundle = (dir_ / "b.bundle").string();
  const std::vector<std::pair<std::function<void(RenderSettings&)>, std::string>> cases = {
      {[](RenderSettings& s) { s.max_depth = 1000; }, "max_depth: must be at most 64 (the depth limit)"},
      {[](RenderSettings& s) { s.width = 20000; }, "width: must be in [1, 16384] (the film's limit)"},
      {[](RenderSettings& s) { s.spp = 4294967295u; }, "spp: 4294967295 spp x 8 x 6 pixels is more than 2^36 samples"},
      // Derived settings a checksum cannot vouch for: a sampler grid of 0 was a SIGFPE, a stream
      // width of 0 or a structure out of range a black image and exit 0.
      {[](RenderSettings& s) { s.grid_n = 0; }, "grid_n: is 0, not the sampler grid of 1 spp"},
      {[](RenderSettings& s) { s.stream_width = 0; }, "stream_width: expected 1 to 16777216 samples in flight, got 0"},
      {[](RenderSettings& s) { s.accel = static_cast<AccelKind>(9); }, "accel: no such value: 9"},
      {[](RenderSettings& s) { s.integrator = static_cast<IntegratorKind>(77); }, "integrator: no such value: 77"},
      {[](RenderSettings& s) { s.target_error = 1e-40f; }, "noise_threshold: noise_threshold 0.000000, target_error"},
  };
  for (const auto& [edit, expected] : cases) {
    SceneBundle b = make_scene_bundle(scene, scene.view(), {0, 1}, scene_path);
    edit(b.scalars.settings);
    write_bundle(bundle, encode_scene_bundle(b));
    std::string output;
    EXPECT_EQ(test::run_command("timeout 30 " + std::string(TRACER_GPU_BINARY) + " render " + bundle + " --device cpu",
                                &output),
              2)
        << expected << "\n"
        << output;
    EXPECT_NE(output.find("b.bundle: the bundle's render settings: " + expected), std::string::npos) << output;
  }
  // The view's grid against its cells: an axis of 0 cells indexed past the cell starts.
  RenderOverrides grid;
  grid.accel = AccelKind::Grid;
  const Scene grid_scene = load_scene(scene_path, grid);
  SceneBundle b = make_scene_bundle(grid_scene, grid_scene.view(), {0, 1}, scene_path);
  b.scalars.grid.n[1] = 0;
  write_bundle(bundle, encode_scene_bundle(b));
  std::string output;
  EXPECT_EQ(test::run_command(std::string(TRACER_GPU_BINARY) + " render " + bundle + " --device cpu", &output), 2);
  EXPECT_NE(output.find("b.bundle: the bundle's view: grid: 0 cells along an axis (1 to 1024)"), std::string::npos)
      << output;
  // The planar mirrors of mirror images index the primitives: an id past them is refused.
  SceneBundle mirrors = make_scene_bundle(scene, scene.view(), {0, 1}, scene_path);
  mirrors.scalars.settings.integrator = IntegratorKind::Path;
  mirrors.scalars.settings.mirror_images = Switch::On;
  mirrors.arrays.mirror_prims = {0};
  write_bundle(bundle, encode_scene_bundle(mirrors));
  EXPECT_EQ(test::run_command(std::string(TRACER_GPU_BINARY) + " render " + bundle + " --device cpu", &output), 2);
  EXPECT_NE(output.find("b.bundle: the bundle's view: mirror_prims: 1 planar mirrors, but the features lack "
                        "mirror-images"),
            std::string::npos)
      << output;  // the GPU would run the path kernel compiled without them
  mirrors.scalars.features |= kFeatureMirrorImages;
  const std::string count = std::to_string(mirrors.arrays.primitives.size());
  mirrors.arrays.mirror_prims = {static_cast<uint32_t>(mirrors.arrays.primitives.size())};
  write_bundle(bundle, encode_scene_bundle(mirrors));
  EXPECT_EQ(test::run_command(std::string(TRACER_GPU_BINARY) + " render " + bundle + " --device cpu", &output), 2);
  EXPECT_NE(
      output.find("b.bundle: the bundle's view: mirror_prims[0]: primitive " + count + " of " + count + " primitives"),
      std::string::npos)
      << output;
  // A declared light's kind is one a scene file declares: any other would be sampled as a point light.
  SceneBundle lit = make_scene_bundle(scene, scene.view(), {0, 1}, scene_path);
  lit.arrays.lights.push_back(Light{LightKind::Shape, {0, 2, 0}, {1, 1, 1}, 0, 0, 0, 0, {0, 0, 0}, 0, 0, 0});
  write_bundle(bundle, encode_scene_bundle(lit));
  EXPECT_EQ(test::run_command(std::string(TRACER_GPU_BINARY) + " render " + bundle + " --device cpu", &output), 2);
  EXPECT_NE(output.find("b.bundle: the bundle's view: lights[0]: kind 3 is not a declared light's"), std::string::npos)
      << output;
  // The declared lights lead the light table, in order (a path that leaves the scene weighs a
  // sun by its entry): a table that starts with another light is refused.
  SceneBundle sun = make_scene_bundle(scene, scene.view(), {0, 1}, scene_path);
  Light parallel{};
  parallel.kind = LightKind::Directional;
  parallel.direction = {0, -1, 0};
  parallel.intensity = {1, 1, 1};
  sun.arrays.lights = {parallel};
  sun.arrays.light_table = {LightEntry{LightKind::Shape, 0, 1.0f, 1.0f}};
  write_bundle(bundle, encode_scene_bundle(sun));
  EXPECT_EQ(test::run_command(std::string(TRACER_GPU_BINARY) + " render " + bundle + " --device cpu", &output), 2);
  EXPECT_NE(output.find("b.bundle: the bundle's view: light_table[0]: not declared light 0"), std::string::npos)
      << output;
  // The GPU's pair records are built from the nodes at upload; records carried in a bundle, which
  // the stream's trace variants would walk unchecked, are refused.
  SceneBundle paired = make_scene_bundle(scene, scene.view(), {0, 1}, scene_path);
  paired.arrays.bvh_pairs.push_back(BvhPairNode{{0, 0, 0}, 1000000, {1, 1, 1}, 0, {0, 0, 0}, 0, {1, 1, 1}, 0});
  write_bundle(bundle, encode_scene_bundle(paired));
  EXPECT_EQ(test::run_command(std::string(TRACER_GPU_BINARY) + " render " + bundle + " --device cpu", &output), 2);
  EXPECT_NE(output.find("b.bundle: the bundle's view: bvh_pairs: pair records are built from bvh_nodes at upload"),
            std::string::npos)
      << output;
  // An --expect that no hash can equal is refused before the render (it rendered, then exited 1).
  write_bundle(bundle, encode_scene_bundle(make_scene_bundle(scene, scene.view(), {0, 1}, scene_path)));
  EXPECT_EQ(
      test::run_command(std::string(TRACER_GPU_BINARY) + " render " + bundle + " --device cpu --expect junk", &output),
      2);
  EXPECT_NE(output.find("--expect junk: expected sha1: and 40 hexadecimal digits"), std::string::npos) << output;
  EXPECT_EQ(output.find("Mrays/s"), std::string::npos) << output;
}

// A thread count the machine cannot start (here: each thread's stack under ulimit -v) is refused
// naming --threads before any work: render exited 1 in the OpenMP runtime's words, tracer-gpu
// and gpu-pack aborted with threads still joinable (gpu-pack's staging directory stayed).
TEST_F(HostileInput, ThreadsTheMachineCannotStartAreRefusedBeforeTheWork) {
#if TRACER_UNDER_ADDRESS_SANITIZER
  GTEST_SKIP() << "ulimit -v cannot hold an AddressSanitizer build (its shadow memory reserves terabytes)";
#endif
  const std::string scene_path = scene_file(scene_text(R"("spp": 1)"));
  const std::string limited = "ulimit -v 2000000 && timeout 60 ";  // 2 GB: 1024 stacks of 8 MB do not fit
  std::string output;
  EXPECT_EQ(test::run_command(limited + TRACER_BINARY + " render " + scene_path + " --threads 1024" + out(), &output),
            2)
      << output;
  EXPECT_NE(output.find("--threads: \"1024\": the machine could not start thread"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
  const std::string bundle = (dir_ / "t.bundle").string();
  const Scene scene = load_scene(scene_path);
  write_bundle(bundle, encode_scene_bundle(make_scene_bundle(scene, scene.view(), {0, 1}, scene_path)));
  EXPECT_EQ(
      test::run_command(limited + TRACER_GPU_BINARY + " render " + bundle + " --device cpu --threads 4096", &output), 2)
      << output;
  EXPECT_NE(output.find("--threads 4096: the machine could not start thread"), std::string::npos) << output;
}

// compare --diff and bench converge --csv/--plot had no check: naming an input (directly,
// through ./ or .., or through a symlink) replaced it with the difference image or the table.
TEST_F(HostileInput, EveryCommandsOutputsNeverNameItsInputs) {
  const Image img = test::image_from(2, 2, [](uint32_t x, uint32_t) { return Vec3{float(x), 0.5f, 0.25f}; });
  write_image(img, (dir_ / "a.exr").string());
  write_image(img, (dir_ / "b.exr").string());
  const std::string a_before = test::read_file(dir_ / "a.exr");
  fs::create_directories(dir_ / "sub");
  fs::create_symlink(dir_ / "a.exr", dir_ / "link.exr");
  const std::string compare = "compare " + (dir_ / "a.exr").string() + " " + (dir_ / "b.exr").string() + " --diff ";
  for (const std::string& diff : {(dir_ / "a.exr").string(), (dir_ / "sub" / ".." / "b.exr").string(),
                                  (dir_ / "link.exr").string(), dir_.string() + "/./a.exr"})
    expect_refused(compare + diff, "--diff names a file this command reads");
  EXPECT_EQ(test::read_file(dir_ / "a.exr"), a_before);
  expect_refused(compare + (dir_ / "d.nosuchformat").string(), "--diff: no image writer");

  const std::string scene = scene_file(scene_text(R"("integrator": "path", "spp": 1)"));
  const std::string scene_before = test::read_file(scene);
  expect_refused("bench converge " + scene + " --spp 1 --ref-spp 1 --csv " + scene,
                 "--csv names a file this command reads");
  expect_refused("bench converge " + scene + " --spp 1 --ref-spp 1 --ref " + (dir_ / "a.exr").string() + " --plot " +
                     (dir_ / "link.exr").string(),
                 "--plot names a file this command reads");
  EXPECT_EQ(test::read_file(scene), scene_before);
  EXPECT_EQ(test::read_file(dir_ / "a.exr"), a_before);

  // merge: -o reaching a part through a symlink would have replaced the part with the image.
  ASSERT_EQ(test::run_tracer("render " + scene + " --quiet --samples 0:1 -o " + (dir_ / "p.partial").string()), 0);
  const std::string part_before = test::read_file(dir_ / "p.partial");
  fs::create_symlink(dir_ / "p.partial", dir_ / "merged.exr");
  expect_refused("merge " + (dir_ / "p.partial").string() + " -o " + (dir_ / "merged.exr").string(),
                 "-o names a file this command reads");
  EXPECT_EQ(test::read_file(dir_ / "p.partial"), part_before);

  // slurm submit: the merge job writes -o at the end, on the cluster; it is checked before
  // anything is submitted or written (no job directory appears).
  const std::string submit = "slurm submit " + scene + " --parts 1 --dir " + (dir_ / "job").string() + " -o ";
  expect_refused(submit + (dir_ / "out.nosuchformat").string(), "-o: no image writer");
  write_image(img, (dir_ / "tex.png").string());
  std::string text =
      scene_text(R"("spp": 1)", R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "t"})");
  text.replace(text.find(R"("materials": {)"), 14,
               R"("materials": {"t": {"type": "lambert", "albedo": {"texture": "tex.png"}}, )");
  expect_refused("slurm submit " + scene_file(text) + " --parts 1 --dir " + (dir_ / "job").string() + " -o " +
                     (dir_ / "sub" / ".." / "tex.png").string(),
                 "-o names a file this command reads");
  EXPECT_FALSE(fs::exists(dir_ / "job"));
}

// The GPU runner's -o wrote its film over the bundle it rendered (directly or through a
// symlink), and was accepted and ignored by the commands that write no film; a device named
// by a file output (--stats /dev/null) was accepted and the render ran before the write failed.
TEST_F(HostileInput, TheRunnersFilmAndEveryFileOutputGoThroughTheOneCheck) {
  const std::string scene = scene_file(scene_text(R"("spp": 1)"));
  const std::string bundle = (dir_ / "s.bundle").string();
  ASSERT_EQ(test::run_tracer("bundle " + scene + " -o " + bundle), 0);
  const std::string bundle_before = test::read_file(bundle);
  fs::create_symlink(bundle, dir_ / "film-link");
  const std::string runner = std::string("timeout 30 ") + TRACER_GPU_BINARY + " ";
  for (const std::string& film : {bundle, (dir_ / "film-link").string(), dir_.string() + "/./s.bundle"}) {
    std::string output;
    EXPECT_EQ(test::run_command(runner + "render " + bundle + " --device cpu -o " + film, &output), 2) << output;
    EXPECT_NE(output.find("-o names a file this command reads"), std::string::npos) << output;
  }
  EXPECT_EQ(test::read_file(bundle), bundle_before);
  std::string output;
  EXPECT_EQ(test::run_command(runner + "pack " + dir_.string() + " --device cpu -o " + (dir_ / "f").string(), &output),
            2);
  EXPECT_NE(output.find("only render writes a film"), std::string::npos) << output;
  EXPECT_EQ(
      test::run_command(runner + "render " + bundle + " --device cpu -o " + (dir_ / "no" / "f").string(), &output), 2);
  EXPECT_NE(output.find("-o: output directory does not exist"), std::string::npos) << output;
  EXPECT_EQ(test::run_command(runner + "render " + bundle + " --device cpu -o " + (dir_ / "f.film").string(), &output),
            0)
      << output;

  // A FIFO stands in for /dev/null: the old code, run as root, replaced the device with a file.
  ASSERT_EQ(::mkfifo((dir_ / "pipe").c_str(), 0600), 0);
  expect_refused("render " + scene + " --stats " + (dir_ / "pipe").string() + out(),
                 "--stats names a device, FIFO or socket");
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
  expect_refused("bundle " + scene + " -o " + (dir_ / "pipe").string(), "-o names a device, FIFO or socket");
  expect_refused("generate cube -o " + (dir_ / "no" / "m.obj").string(), "-o: output directory does not exist");
  expect_refused("bench converge " + scene + " --spp 1 --ref-spp 1 --csv " + dir_.string(), "--csv names a directory");
}

}  // namespace
}  // namespace tracer
