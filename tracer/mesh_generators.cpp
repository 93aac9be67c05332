#include "mesh_generators.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unordered_map>

#include "input_error.h"
#include "kernel/detmath.h"
#include "text_file.h"

namespace tracer {
namespace {

MeshTriangle triangle(Vec3 a, Vec3 b, Vec3 c) {
  MeshTriangle t{};
  t.p[0] = a, t.p[1] = b, t.p[2] = c;
  return t;
}

// Two triangles of the quad a b c d (counter-clockwise).
void quad(std::vector<MeshTriangle>& out, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  out.push_back(triangle(a, b, c));
  out.push_back(triangle(a, c, d));
}

void box(std::vector<MeshTriangle>& out, Vec3 lo, Vec3 hi) {
  const Vec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                     {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  quad(out, c[0], c[3], c[2], c[1]);
  quad(out, c[4], c[5], c[6], c[7]);
  quad(out, c[0], c[1], c[5], c[4]);
  quad(out, c[3], c[7], c[6], c[2]);
  quad(out, c[0], c[4], c[7], c[3]);
  quad(out, c[1], c[2], c[6], c[5]);
}

// A value in [0, 1) from an integer (splitmix64's finaliser).
float hash01(uint64_t k) {
  k = (k ^ (k >> 30)) * 0xBF58476D1CE4E5B9ull;
  k = (k ^ (k >> 27)) * 0x94D049BB133111EBull;
  return static_cast<float>((k ^ (k >> 31)) >> 40) * 0x1p-24f;
}

float sine_sum(float u, float v) {
  return 0.25f * det_sin(3.1f * u + 0.7f) * det_cos(2.3f * v) + 0.12f * det_sin(7.7f * u + 5.3f * v) +
         0.05f * det_cos(17.0f * u - 11.0f * v + 1.0f);
}

void terrain(std::vector<MeshTriangle>& out, uint32_t triangles) {
  const uint32_t n = std::max(1u, static_cast<uint32_t>(std::lround(std::sqrt(triangles / 2.0))));
  const auto at = [&](uint32_t i, uint32_t j) {
    const float u = static_cast<float>(i) / n, v = static_cast<float>(j) / n;
    return Vec3{u * 4.0f - 2.0f, sine_sum(u * 4.0f, v * 4.0f), v * 4.0f - 2.0f};
  };
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) quad(out, at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
}

void sphere(std::vector<MeshTriangle>& out, uint32_t triangles, Vec3 centre, float radius) {
  const uint32_t stacks = std::max(3u, static_cast<uint32_t>(std::lround(std::sqrt(triangles / 4.0)))), slices = 2 * stacks;
  const auto at = [&](uint32_t i, uint32_t j) {
    const float theta = kPi * static_cast<float>(j) / stacks, phi = 2.0f * kPi * static_cast<float>(i % slices) / slices;
    const Vec3 d = {det_sin(theta) * det_cos(phi), det_cos(theta), det_sin(theta) * det_sin(phi)};
    const float r = radius * (1.0f + 0.15f * sine_sum(2.0f * phi, 3.0f * theta));
    return centre + d * r;
  };
  for (uint32_t j = 0; j < stacks; ++j)
    for (uint32_t i = 0; i < slices; ++i) {
      const Vec3 a = at(i, j), b = at(i, j + 1), c = at(i + 1, j + 1), d = at(i + 1, j);
      if (j > 0) out.push_back(triangle(a, b, d));
      if (j + 1 < stacks) out.push_back(triangle(b, c, d));
    }
}

void cubes(std::vector<MeshTriangle>& out, uint32_t count) {
  for (uint32_t k = 0; k < count; ++k) {
    const Vec3 c = {hash01(3 * k) * 8.0f - 4.0f, hash01(3 * k + 1) * 4.0f, hash01(3 * k + 2) * 8.0f - 4.0f};
    const float s = 0.05f + 0.1f * hash01(k + 0x51ED);
    box(out, c - Vec3{s, s, s}, c + Vec3{s, s, s});
  }
}

}  // namespace

const std::vector<std::string>& mesh_generator_kinds() {
  static const std::vector<std::string> kinds = {"terrain", "sphere", "boxes", "cubes", "mixed"};
  return kinds;
}

std::vector<MeshTriangle> generate_mesh(const std::string& kind, uint32_t triangles) {
  std::vector<MeshTriangle> out;
  if (kind == "terrain") {
    terrain(out, triangles);
  } else if (kind == "sphere") {
    sphere(out, triangles, {0, 0, 0}, 1.0f);
  } else if (kind == "boxes") {
    box(out, {-1.5f, 0, -0.5f}, {-0.5f, 1, 0.5f});
    box(out, {-0.4f, 0, -0.3f}, {0.4f, 1.6f, 0.3f});
    box(out, {0.6f, 0, -0.2f}, {1.4f, 0.6f, 0.6f});
  } else if (kind == "cubes") {
    cubes(out, std::max(1u, triangles / 12));
  } else if (kind == "mixed") {
    sphere(out, triangles - triangles / 6, {0, 1.5f, 0}, 1.2f);
    cubes(out, std::max(1u, triangles / 6 / 12));
  } else {
    std::string list;
    for (const std::string& k : mesh_generator_kinds()) list += (list.empty() ? "" : ", ") + k;
    throw InputError("generate " + kind + ": unknown mesh kind (expected " + list + ")");
  }
  return out;
}

void write_obj(const std::vector<MeshTriangle>& mesh, const std::string& path) {
  // Vertices shared by bit-identical positions, numbered in order of first use.
  std::unordered_map<uint64_t, std::vector<std::pair<uint32_t, size_t>>> index;  // hash -> (z bits, number)
  std::string vertices, faces;
  size_t count = 0;
  char line[128];
  const auto vertex = [&](Vec3 p) {
    const uint64_t key = uint64_t(bits_of(p.x)) << 32 | bits_of(p.y);
    for (const auto& [z, number] : index[key])
      if (z == bits_of(p.z)) return number;
    index[key].push_back({bits_of(p.z), ++count});
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
    vertices += line;
    return count;
  };
  for (const MeshTriangle& t : mesh) {
    const size_t a = vertex(t.p[0]), b = vertex(t.p[1]), c = vertex(t.p[2]);
    std::snprintf(line, sizeof line, "f %zu %zu %zu\n", a, b, c);
    faces += line;
  }
  write_text_atomically(path, "# tracer generate: " + std::to_string(mesh.size()) + " triangles\n" + vertices + faces);
}

}  // namespace tracer
