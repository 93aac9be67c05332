// Debian's assimp-testmodels as a corpus for the glTF reader (docs/gltf.md): every glTF 2.0
// file in it loads, or is refused with an InputError that names the file and says what; the
// broken ones (assimp's own negative tests) are all refused; none crashes or hangs. Skipped,
// with the reason, where the package is not installed (ci/install-deps.sh installs it).
#include <gtest/gtest.h>

#include <chrono>
#include <set>

#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

const fs::path kCorpus = "/usr/share/assimp/models/glTF2";

// Files that break the specification: each must be refused.
const std::set<std::string> kBroken = {
    "BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb",  // non-finite positions
    "IndexOutOfRange/AllIndicesOutOfRange.gltf",
    "IndexOutOfRange/IndexOutOfRange.gltf",
    "MissingBin/BoxTextured.gltf",         // its buffer's file is absent
    "RecursiveNodes/RecursiveNodes.gltf",  // a node cycle
    "SchemaFailures/sceneWrongType.gltf",  // "scene": "hello"
    "wrongTypes/badArray.gltf",            // properties of the wrong JSON type
    "wrongTypes/badExtension.gltf",
    "wrongTypes/badNumber.gltf",
    "wrongTypes/badObject.gltf",
    "wrongTypes/badString.gltf",
    "wrongTypes/badUint.gltf",
    "BoxBadNormals-glTF-Binary/BoxBadNormals.glb",  // zero normals
};

TEST(GltfCorpus, EveryFileLoadsOrIsRefusedByName) {
  if (!fs::is_directory(kCorpus)) GTEST_SKIP() << kCorpus << " is absent: Debian's assimp-testmodels is not installed";
  const auto start = std::chrono::steady_clock::now();
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(kCorpus))
    if (e.path().extension() == ".gltf" || e.path().extension() == ".glb") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 40u);
  size_t loaded = 0, broken_seen = 0;
  RenderOverrides ov;
  ov.width = 8;
  for (const fs::path& file : files) {
    const std::string name = fs::relative(file, kCorpus).string();
    const bool broken = kBroken.count(name) > 0;
    broken_seen += broken;
    try {
      const Scene scene = load_scene(file.string(), ov);
      EXPECT_FALSE(broken) << name << " is broken but loaded";
      EXPECT_GT(scene.primitives.size(), 0u) << name;
      ++loaded;
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind(file.string() + ": ", 0), 0u) << what;  // names the file first, then why
      EXPECT_GT(what.size(), file.string().size() + 10) << what;
    }
  }
  EXPECT_EQ(broken_seen, kBroken.size());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("glTF corpus: %zu files, %zu loaded, %zu refused (%zu of them broken), %.1f s\n", files.size(), loaded,
              files.size() - loaded, kBroken.size(), seconds);
}

TEST(GltfCorpus, TheCommandLineExitsTwoOnEveryBrokenFile) {
  if (!fs::is_directory(kCorpus)) GTEST_SKIP() << kCorpus << " is absent: Debian's assimp-testmodels is not installed";
  const fs::path out = test::temp_dir("gltf-corpus") / "out.png";
  for (const std::string& name : kBroken) {
    std::string output;
    EXPECT_EQ(test::run_command("timeout 30 " + std::string(TRACER_BINARY) + " render " + (kCorpus / name).string() +
                                    " --width 8 --quiet -o " + out.string(),
                                &output),
              2)
        << name << "\n"
        << output;
    EXPECT_FALSE(fs::exists(out)) << name;
  }
  fs::remove_all(out.parent_path());
}

}  // namespace
}  // namespace tracer
