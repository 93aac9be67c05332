// Helpers shared by the tests: scenes from inline JSON, temporary directories, running
// the CLI.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "image_io.h"
#include "scene_loader.h"

namespace tracer::test {

// A fixed stream of test inputs (splitmix64): the same numbers on every run and machine.
struct InputStream {
  uint64_t state;
  uint64_t next_bits() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  float next() { return static_cast<float>(next_bits() >> 40) * 0x1p-24f; }  // uniform in [0, 1)
};

inline std::filesystem::path temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("tracer-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline Scene scene_from(const std::string& json, const RenderOverrides& ov = {}) {
  return load_scene_text(json, "inline.json", ov);
}

// Writes six size x size cube faces f0.exr .. f5.exr (+x, -x, +y, -y, +z, -z) into dir,
// texel (x, y) of face i coloured texel(i, x, y); returns the quoted names for "faces".
template <class TexelColour>
std::string write_cube_faces(const std::filesystem::path& dir, int size, TexelColour texel) {
  std::string list;
  for (int i = 0; i < 6; ++i) {
    Image img{uint32_t(size), uint32_t(size), {}};
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const Vec3 c = texel(i, x, y);
        img.rgb.insert(img.rgb.end(), {c.x, c.y, c.z});
      }
    const std::string name = "f" + std::to_string(i) + ".exr";
    write_image(img, (dir / name).string());
    list += (i ? ", \"" : "\"") + name + "\"";
  }
  return list;
}

inline std::string source_path(const std::string& rel) { return std::string(TRACER_SOURCE_DIR) + "/" + rel; }

// The scene files every test may use: each .json under scenes/ except scenes/large/, whose
// meshes ci/generate-meshes.sh writes at set-up (test_scene_loader.cpp checks those).
inline std::vector<std::filesystem::path> shipped_scenes() {
  std::vector<std::filesystem::path> out;
  const std::filesystem::path large = std::filesystem::path(source_path("scenes")) / "large";
  for (const auto& e : std::filesystem::recursive_directory_iterator(source_path("scenes")))
    if (e.path().extension() == ".json" && e.path().parent_path() != large) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// Runs a shell command; returns its exit code and captures stderr+stdout.
inline int run_command(const std::string& command, std::string* output = nullptr) {
  const auto log = std::filesystem::temp_directory_path() / ("tracer-cmd-" + std::to_string(::getpid()) + ".log");
  const std::string cmd = "(" + command + ") >" + log.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  if (output) {
    FILE* f = std::fopen(log.c_str(), "rb");
    output->clear();
    if (f) {
      char buf[4096];
      size_t n;
      while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) output->append(buf, n);
      std::fclose(f);
    }
  }
  std::filesystem::remove(log);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Runs the tracer binary with `args`.
inline int run_tracer(const std::string& args, std::string* output = nullptr) {
  return run_command(std::string(TRACER_BINARY) + " " + args, output);
}

}  // namespace tracer::test
