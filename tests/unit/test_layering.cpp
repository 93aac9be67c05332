// The source folders' layers (README, "Layout"): a file of tracer/F includes headers of F and
// of the folders below it only, and kernel code includes kernel headers only (it compiles for
// CUDA). Lowest first: kernel, io, options, accel, image, scene, bundle, render, then the tools
// (golden, bench, audit, cluster, view), then cli.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

const std::map<std::string, int> kLayer = {{"kernel", 0}, {"io", 1},      {"options", 2}, {"accel", 3},  {"image", 4},
                                           {"scene", 5},  {"bundle", 6},  {"render", 7},  {"golden", 8}, {"bench", 8},
                                           {"audit", 8},  {"cluster", 8}, {"view", 8}, {"cli", 9}};

// Every `#include "FOLDER/..."` of the files under tracer/, as (file, its folder, included folder).
struct Include {
  std::string file, from, to;
};

std::vector<Include> folder_includes() {
  std::vector<Include> found;
  const fs::path root = fs::path(TRACER_SOURCE_DIR) / "tracer";
  const std::regex include(R"re(^\s*#\s*include\s+"([a-z_]+)/)re");
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    const std::string from = fs::relative(entry.path(), root).begin()->string();
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);) {
      std::smatch m;
      if (std::regex_search(line, m, include) && kLayer.count(m[1]))
        found.push_back({fs::relative(entry.path(), TRACER_SOURCE_DIR).string(), from, m[1]});
    }
  }
  return found;
}

TEST(Layering, NoFolderIncludesOneAboveIt) {
  const std::vector<Include> includes = folder_includes();
  ASSERT_GT(includes.size(), 500u) << "the scan found too few includes to mean anything";
  for (const Include& i : includes) {
    ASSERT_TRUE(kLayer.count(i.from)) << i.file << ": tracer/" << i.from << " has no layer in this test";
    EXPECT_LE(kLayer.at(i.to), kLayer.at(i.from))
        << i.file << " (" << i.from << ") includes " << i.to << "/, a higher layer";
  }
}

TEST(Layering, EveryFolderOfTracerHasALayer) {
  for (const auto& entry : fs::directory_iterator(fs::path(TRACER_SOURCE_DIR) / "tracer"))
    if (entry.is_directory()) {
      EXPECT_TRUE(kLayer.count(entry.path().filename().string())) << entry.path();
    }
}

}  // namespace
}  // namespace tracer
