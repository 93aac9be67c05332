// The hostile-input tests' scene, helpers and fixture (tests/unit/test_hostile_*.cpp): the
// tracer under a time limit, a one-sphere scene with its render settings and shapes
// replaceable, a scratch directory per test, and image files whose headers lie.
#pragma once
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "test_util.h"

namespace tracer {

namespace fs = std::filesystem;

inline constexpr const char* kScene =
    R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40},
  "film": {"width": 8, "height": 6}, "render": {RENDER}, "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
  "shapes": [SHAPES]})";
inline constexpr const char* kSphere = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"})";

inline std::string scene_text(const std::string& render, const std::string& shapes = kSphere) {
  std::string s = kScene;
  s.replace(s.find("RENDER"), 6, render);
  s.replace(s.find("SHAPES"), 6, shapes);
  return s;
}

inline void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// The tracer under a 30 s limit: a hang fails the test instead of the CI runner.
inline int run_limited(const std::string& args, std::string& output) {
  return test::run_command("timeout 30 " + std::string(TRACER_BINARY) + " " + args, &output);
}

inline void expect_refused(const std::string& args, const std::string& expected) {
  std::string output;
  const std::string shown = args.substr(0, 300);  // arguments may be huge
  EXPECT_EQ(run_limited(args, output), 2) << shown << "\n" << output.substr(0, 1000);
  EXPECT_NE(output.find(expected), std::string::npos) << shown << "\n" << output.substr(0, 1000);
}

class HostileInput : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::temp_dir("hostile"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string scene_file(const std::string& text) {
    write(dir_ / "s.json", text);
    return (dir_ / "s.json").string();
  }
  std::string out() const { return " --quiet -o " + (dir_ / "out.png").string(); }
  // A real 2 x 2 render as EXR bytes; s.json is its scene.
  std::string small_exr() {
    scene_file(scene_text(R"("spp": 1)"));
    std::string output;
    EXPECT_EQ(test::run_tracer("render " + (dir_ / "s.json").string() + " --quiet --width 2 --height 2 -o " +
                                   (dir_ / "small.exr").string(),
                               &output),
              0)
        << output;
    return test::read_file(dir_ / "small.exr");
  }
  fs::path dir_;
};

// A real EXR's header rewritten to declare side x side pixels (data and display windows, and a
// line-offset table of that many chunks pointing past the end): a small file, a huge image.
inline std::string exr_declaring(std::string exr, int32_t side) {
  for (const std::string& name : {std::string("dataWindow\0box2i\0", 17), std::string("displayWindow\0box2i\0", 20)}) {
    const size_t at = exr.find(name);
    EXPECT_NE(at, std::string::npos);
    const int32_t box[4] = {0, 0, side - 1, side - 1};
    exr.replace(at + name.size() + 4, 16, reinterpret_cast<const char*>(box), 16);
  }
  size_t end = 8;  // attributes: name\0 type\0 size value, up to an empty name
  while (exr[end] != '\0') {
    const size_t type_end = exr.find('\0', exr.find('\0', end) + 1);
    int32_t size;
    std::memcpy(&size, exr.data() + type_end + 1, 4);
    end = type_end + 5 + size;
  }
  ++end;
  const uint64_t chunks = (side + 15) / 16, first = end + 8 * chunks;  // 16 lines a chunk (zip)
  std::string table;
  for (uint64_t i = 0; i < chunks; ++i) table.append(reinterpret_cast<const char*>(&first), 8);
  exr = exr.substr(0, end) + table + exr.substr(end + 8);
  return exr;
}

}  // namespace tracer
