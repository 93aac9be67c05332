// The glTF scenes of scenes/gltf/ (docs/gltf.md): the Cornell box as glTF renders the image of
// its JSON twin bit for bit, in both integrators; `tracer render FILE.glb` writes an image,
// and refuses a bad camera or background with exit 2 and nothing written.
#include <gtest/gtest.h>

#include <cstring>
#include <nlohmann/json.hpp>

#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

const std::string kDir = std::string(TRACER_SOURCE_DIR) + "/scenes/gltf/";

Image render_small(const std::string& file, IntegratorKind integrator) {
  RenderOverrides ov;
  ov.width = 64;
  ov.height = 48;
  ov.spp = 4;
  ov.integrator = integrator;
  RenderStats stats;
  return render_cpu(load_scene(kDir + file, ov), 1, stats);
}

TEST(GltfScenes, TheCornellBoxAsGltfAndAsJsonRenderTheSameImage) {
  for (const IntegratorKind integrator : {IntegratorKind::Path, IntegratorKind::Whitted}) {
    const Image gltf = render_small("cornell-box.gltf", integrator);
    const Image json = render_small("cornell-box-twin.json", integrator);
    ASSERT_EQ(gltf.rgb.size(), json.rgb.size());
    EXPECT_EQ(std::memcmp(gltf.rgb.data(), json.rgb.data(), gltf.rgb.size() * sizeof(float)), 0)
        << "integrator " << static_cast<int>(integrator);
    float sum = 0.0f;
    for (float v : gltf.rgb) sum += v;
    EXPECT_GT(sum, 0.0f);  // the lamp lights the box
  }
}

// cornell-box.gltf as a `gltf` shape of a JSON scene, with the twin's camera and settings:
// the same primitives and image as the twin; through a transform, every corner moved by it.
TEST(GltfScenes, AGltfShapeInAJsonSceneIsItsFilesTriangles) {
  const std::string twin = test::read_file(kDir + "cornell-box-twin.json");
  nlohmann::json doc = nlohmann::json::parse(twin);
  doc["materials"] = nlohmann::json::object();
  doc["shapes"] = {{{"type", "gltf"}, {"file", "cornell-box.gltf"}}};
  RenderOverrides ov;
  ov.width = 64;
  ov.height = 48;
  ov.spp = 4;
  const Scene included = load_scene_text(doc.dump(), kDir + "included.json", ov);
  const Scene reference = load_scene(kDir + "cornell-box-twin.json", ov);
  ASSERT_EQ(included.primitives.size(), reference.primitives.size());
  for (size_t i = 0; i < included.primitives.size(); ++i) {
    EXPECT_EQ(included.primitives[i].a, reference.primitives[i].a) << i;
    EXPECT_EQ(included.primitives[i].c, reference.primitives[i].c) << i;
  }
  RenderStats stats;
  const Image a = render_cpu(included, 1, stats), b = render_cpu(reference, 1, stats);
  EXPECT_EQ(std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)), 0);
  doc["shapes"][0]["transform"] = {{{"translate", {0.5, 0, -2}}}};
  const Scene moved = load_scene_text(doc.dump(), kDir + "included.json", ov);
  EXPECT_EQ(moved.primitives[0].a, reference.primitives[0].a + Vec3(0.5f, 0.0f, -2.0f));
  EXPECT_EQ(moved.report.shape_counts.at("gltf"), 1u);
}

TEST(GltfScenes, RenderFromTheCommandLine) {
  const fs::path dir = test::temp_dir("gltf-cli");
  const std::string out = (dir / "out.png").string();
  std::string output;
  for (const std::string file : {"textured.glb", "sphere-grid.glb", "cornell-box.gltf"}) {
    EXPECT_EQ(test::run_tracer("render " + kDir + file + " --spp 1 --width 24 --quiet -o " + out, &output), 0)
        << output;
    EXPECT_TRUE(fs::exists(out)) << file;
    fs::remove(out);
  }
  EXPECT_EQ(test::run_tracer("render " + kDir + "textured.glb --camera nobody --quiet -o " + out, &output), 2);
  EXPECT_NE(output.find("--camera: no perspective camera \"nobody\" in the file (it places 0 \"front\")"),
            std::string::npos)
      << output;
  EXPECT_EQ(test::run_tracer("render " + kDir + "textured.glb --background 1,2 --quiet -o " + out, &output), 2);
  EXPECT_NE(output.find("--background: expected R,G,B"), std::string::npos) << output;
  EXPECT_EQ(test::run_tracer("render " + kDir + "cornell-box-twin.json --camera 0 --quiet -o " + out, &output), 2);
  EXPECT_NE(output.find("--camera: for glTF files"), std::string::npos) << output;
  EXPECT_FALSE(fs::exists(out));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tracer
