// Helpers shared by the tests: scenes from inline JSON, temporary directories, images,
// loader errors, pixel differences, running the CLI.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <functional>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "io/input_error.h"
#include "kernel/light/light.h"
#include "render/render_cpu.h"
#include "scene/scene_loader.h"

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

// A file's bytes ("" when it cannot be opened).
// A sample of the scene's environment light seen from the origin, by three draws of s (the
// direction's two, then the cell's), as the sampling tests take them.
inline LightSample draw_environment(const SceneView& view, InputStream& s) {
  const float u1 = s.next(), u2 = s.next(), cell_u = s.next();
  return sample_light(view, view.environment_light, {0, 0, 0}, u1, u2, cell_u);
}

// The mean of channel c over an image's pixels, and its standard error.
struct MeanStat {
  double mean, stderr_;
};
inline MeanStat channel_mean(const Image& img, int c) {
  const size_t n = img.rgb.size() / 3;
  double sum = 0, sum2 = 0;
  for (size_t i = 0; i < n; ++i) sum += img.rgb[3 * i + c], sum2 += double(img.rgb[3 * i + c]) * img.rgb[3 * i + c];
  const double mean = sum / n, var = std::max(0.0, sum2 / n - mean * mean) * n / (n - 1);
  return {mean, std::sqrt(var / n)};
}

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

inline std::filesystem::path temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("tracer-test-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline Scene scene_from(const std::string& json, const RenderOverrides& ov = {}) {
  return load_scene_text(json, "inline.json", ov);
}

// A w x h image whose texel (x, y) is texel(x, y).
inline Image image_from(uint32_t w, uint32_t h, const std::function<Vec3(uint32_t x, uint32_t y)>& texel) {
  Image img{w, h, {}};
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      const Vec3 c = texel(x, y);
      img.rgb.insert(img.rgb.end(), {c.x, c.y, c.z});
    }
  return img;
}

// Renders a scene given as JSON as if its file were dir/s.json (its textures beside it).
inline Image render_in(const std::filesystem::path& dir, const std::string& json) {
  RenderStats stats;
  return render_cpu(load_scene_text(json, (dir / "s.json").string()), 1, stats);
}

// Loading the JSON as dir/s.json fails with an InputError whose message contains `expected`.
inline void expect_load_error(const std::filesystem::path& dir, const std::string& json, const std::string& expected) {
  try {
    load_scene_text(json, (dir / "s.json").string());
    ADD_FAILURE() << "accepted " << json;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}

// Distance along the ray (unit direction) to the sphere's near side, in double; -1 on a miss.
inline double ray_sphere_distance(const Ray& r, double cx, double cy, double cz, double radius) {
  const double ox = r.origin.x - cx, oy = r.origin.y - cy, oz = r.origin.z - cz;
  const double b = ox * r.dir.x + oy * r.dir.y + oz * r.dir.z, q = ox * ox + oy * oy + oz * oz - radius * radius;
  const double disc = b * b - q;
  return disc < 0 ? -1.0 : -b - std::sqrt(disc);
}

// Per pixel, the largest difference of its channels between two images of one size.
struct PixelDifferences {
  std::vector<double> pixels;
  double max() const { return pixels.empty() ? 0.0 : *std::max_element(pixels.begin(), pixels.end()); }
  double mean() const {
    double sum = 0;
    for (double d : pixels) sum += d;
    return pixels.empty() ? 0.0 : sum / static_cast<double>(pixels.size());
  }
  size_t count_over(double threshold) const {
    return static_cast<size_t>(std::count_if(pixels.begin(), pixels.end(), [&](double d) { return d > threshold; }));
  }
  double fraction_over(double threshold) const {
    return static_cast<double>(count_over(threshold)) / static_cast<double>(pixels.size());
  }
};

inline PixelDifferences pixel_differences(const Image& a, const Image& b) {
  PixelDifferences d;
  for (size_t i = 0; i + 2 < a.rgb.size(); i += 3) {
    double p = 0;
    for (int c = 0; c < 3; ++c) p = std::max(p, std::abs(static_cast<double>(a.rgb[i + c]) - b.rgb[i + c]));
    d.pixels.push_back(p);
  }
  return d;
}

// Writes six size x size cube faces f0.exr .. f5.exr (+x, -x, +y, -y, +z, -z) into dir,
// texel (x, y) of face i coloured texel(i, x, y); returns the quoted names for "faces".
template <class TexelColour>
std::string write_cube_faces(const std::filesystem::path& dir, int size, TexelColour texel) {
  std::string list;
  for (int i = 0; i < 6; ++i) {
    const Image img =
        image_from(uint32_t(size), uint32_t(size), [&](uint32_t x, uint32_t y) { return texel(i, int(x), int(y)); });
    const std::string name = "f" + std::to_string(i) + ".exr";
    write_image(img, (dir / name).string());
    list += (i ? ", \"" : "\"") + name + "\"";
  }
  return list;
}

// The goldens that stand for all of them on an axis where rendering every golden would repeat
// what another test proves ray by ray (the structures: AccelIdentity's hits on every shipped
// scene): one of each integrator (Whitted, path, a view, adaptive), mirror images, a triangle
// mesh, a textured glTF file, the scene that holds most features, and a sun (shadow rays with
// no end, through every structure).
inline const std::vector<std::string>& representative_goldens() {
  static const std::vector<std::string> names = {
      "cornell-box", "cornell-box-path", "cornell-box-normals",    "cornell-box-adaptive",
      "mesh",        "gltf-textured",    "cornell-box-mirror-box", "showcase",
      "sun"};
  return names;
}

inline bool is_representative_golden(const std::string& name) {
  const auto& names = representative_goldens();
  return std::find(names.begin(), names.end(), name) != names.end();
}

inline std::string source_path(const std::string& rel) { return std::string(TRACER_SOURCE_DIR) + "/" + rel; }

// The scene files every test may use: each .json under scenes/ except scenes/large/, whose
// meshes ci/generate-meshes.sh writes at set-up (test_scene_loader.cpp checks those), and
// except scenes/generated/ and below, git-ignored output of `tracer generate`, benchmarks and
// fetched tools.
inline std::vector<std::filesystem::path> shipped_scenes() {
  std::vector<std::filesystem::path> out;
  const std::filesystem::path root(source_path("scenes")), large = root / "large", generated = root / "generated";
  for (auto e = std::filesystem::recursive_directory_iterator(root);
       e != std::filesystem::recursive_directory_iterator(); ++e) {
    if (e->path() == generated) e.disable_recursion_pending();
    if (e->path().extension() == ".json" && e->path().parent_path() != large && e->path().parent_path() != generated)
      out.push_back(e->path());
  }
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
