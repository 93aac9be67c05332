#include "bench/mesh_generators.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unordered_map>

#include "io/input_error.h"
#include "io/output_batch.h"
#include "kernel/base/detmath.h"

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
  const uint32_t stacks = std::max(3u, static_cast<uint32_t>(std::lround(std::sqrt(triangles / 4.0)))),
                 slices = 2 * stacks;
  const auto at = [&](uint32_t i, uint32_t j) {
    const float theta = kPi * static_cast<float>(j) / stacks,
                phi = 2.0f * kPi * static_cast<float>(i % slices) / slices;
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

// A closed icosphere of radius 1: the icosahedron with each triangle split into four,
// `levels` times, midpoints pushed onto the sphere. Both triangles at an edge compute its
// midpoint from the same two points (a + b is symmetric), so shared vertices are identical.
void icosphere(std::vector<MeshTriangle>& out, uint32_t triangles) {
  const float g = 1.6180339887f;  // the golden ratio
  const Vec3 v[12] = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                      {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  const int f[20][3] = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  std::vector<MeshTriangle> mesh;
  for (const auto& t : f) mesh.push_back(triangle(normalize(v[t[0]]), normalize(v[t[1]]), normalize(v[t[2]])));
  while (mesh.size() * 4 <= triangles) {
    std::vector<MeshTriangle> finer;
    for (const MeshTriangle& t : mesh) {
      const Vec3 ab = normalize(t.p[0] + t.p[1]), bc = normalize(t.p[1] + t.p[2]), ca = normalize(t.p[2] + t.p[0]);
      finer.push_back(triangle(t.p[0], ab, ca));
      finer.push_back(triangle(ab, t.p[1], bc));
      finer.push_back(triangle(ca, bc, t.p[2]));
      finer.push_back(triangle(ab, bc, ca));
    }
    mesh.swap(finer);
  }
  out.insert(out.end(), mesh.begin(), mesh.end());
}

// The closed cube [-1, 1]^3, each face an n x n grid of quad pairs; every grid coordinate
// comes from one expression, so faces meet at identical vertices.
void grid_cube(std::vector<MeshTriangle>& out, uint32_t triangles) {
  const uint32_t n = std::max(1u, static_cast<uint32_t>(std::lround(std::sqrt(triangles / 12.0))));
  const auto c = [n](uint32_t k) { return -1.0f + 2.0f * static_cast<float>(k) / static_cast<float>(n); };
  for (int axis = 0; axis < 3; ++axis)
    for (const float side : {-1.0f, 1.0f}) {
      const auto at = [&](uint32_t i, uint32_t j) {
        Vec3 p{0, 0, 0};
        p[axis] = side;
        p[(axis + 1) % 3] = c(i);
        p[(axis + 2) % 3] = c(j);
        return p;
      };
      for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
          if (side > 0)
            quad(out, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
          else
            quad(out, at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));  // outward winding
        }
    }
}

}  // namespace

const std::vector<std::string>& mesh_generator_kinds() {
  static const std::vector<std::string> kinds = {"terrain", "sphere", "boxes", "cubes", "mixed", "icosphere", "cube"};
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
  } else if (kind == "icosphere") {
    icosphere(out, triangles);
  } else if (kind == "cube") {
    grid_cube(out, triangles);
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
  write_file_atomically(path, "# tracer generate: " + std::to_string(mesh.size()) + " triangles\n" + vertices + faces);
}

}  // namespace tracer
