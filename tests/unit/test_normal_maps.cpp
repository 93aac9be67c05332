// Normal, bump and specular maps: maps that describe the unperturbed surface change nothing,
// bit for bit; a tilted normal map tilts the Lambert cosine as predicted.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "image/image_io.h"
#include "io/input_error.h"
#include "render/render_cpu.h"
#include "scene/mesh_tangents.h"
#include "test_util.h"

namespace tracer {
namespace {

// A quad facing +z under a point light, seen head-on, with `extra` material keys.
std::string lit_quad(const std::string& extra, const std::string& integrator = "whitted") {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 2], "to": [0, 0, 0], "vfov": 60},
    "film": {"width": 32, "height": 32}, "render": {"integrator": ")" +
         integrator + R"(", "sampler": "center", "max_depth": 1},
    "materials": {"m": {"type": "phong", "diffuse": [0.6, 0.6, 0.6], "specular": [0.3, 0.3, 0.3], "shininess": 20)" +
         extra + R"(}},
    "lights": [{"type": "point", "position": [0.7, 0.4, 1.5], "intensity": [3, 3, 3]}],
    "shapes": [{"type": "quad", "corner": [-1, -1, 0], "u": [2, 0, 0], "v": [0, 2, 0], "material": "m"},
               {"type": "sphere", "center": [0.5, -0.4, 0.3], "radius": 0.3, "material": "m"}]})";
}

Image constant_image(uint32_t n, float r, float g, float b) {
  return test::image_from(n, n, [&](uint32_t, uint32_t) { return Vec3{r, g, b}; });
}

using test::render_in;

bool same_bits(const Image& a, const Image& b) {
  return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

TEST(NormalMaps, FlatNormalMapAndConstantBumpMapChangeNothing) {
  const auto dir = test::temp_dir("maps-flat");
  write_image(constant_image(8, 0.5f, 0.5f, 1.0f), (dir / "flat.exr").string());
  write_image(constant_image(8, 0.3f, 0.3f, 0.3f), (dir / "height.exr").string());
  write_image(constant_image(8, 1.0f, 1.0f, 1.0f), (dir / "white.exr").string());
  for (const char* integrator : {"whitted", "path", "normals"}) {
    const Image plain = render_in(dir, lit_quad("", integrator));
    EXPECT_TRUE(same_bits(plain, render_in(dir, lit_quad(R"(, "normal_map": "flat.exr")", integrator)))) << integrator;
    EXPECT_TRUE(same_bits(plain, render_in(dir, lit_quad(R"(, "bump_map": "height.exr")", integrator)))) << integrator;
    EXPECT_TRUE(same_bits(plain, render_in(dir, lit_quad(R"(, "specular_map": "white.exr")", integrator))))
        << integrator;
  }
  std::filesystem::remove_all(dir);
}

// A normal map of (sin a, 0, cos a) in tangent space tilts the quad's normal toward +x (its
// u direction, the tangent) by a, and one of (0, sin a, cos a) toward +y (its v direction,
// the bitangent n x t). With the light at (1, 0, 1), or (0, 1, 1), from the centre pixel the
// path tracer's direct light there is albedo I (n . l) / (pi d^2) with the tilted n; a tilt
// the wrong way along either axis gives cos a - sin a instead of cos a + sin a.
TEST(NormalMaps, TiltedNormalMapTiltsTheCosine) {
  const auto dir = test::temp_dir("maps-tilt");
  const float a = 0.5f;
  const double tilted = 2.0 * (0.5 + 0.5 * std::sin(a)) - 1.0, up = 2.0 * (0.5 + 0.5 * std::cos(a)) - 1.0;
  const double cos = (tilted + up) / std::sqrt(2.0) / std::sqrt(tilted * tilted + up * up);
  const double expected = 0.5 / M_PI * 2.0 * cos / 2.0;  // d^2 = 2 from the point (0, 0, 0)
  for (const bool along_v : {false, true}) {
    const float t = 0.5f + 0.5f * std::sin(a);
    write_image(constant_image(4, along_v ? 0.5f : t, along_v ? t : 0.5f, 0.5f + 0.5f * std::cos(a)),
                (dir / "tilt.exr").string());
    const std::string scene =
        R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 2], "to": [0, 0, 0], "vfov": 60},
      "film": {"width": 33, "height": 33}, "render": {"integrator": "path", "sampler": "center", "max_depth": 1},
      "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5], "normal_map": "tilt.exr"}},
      "lights": [{"type": "point", "position": )" +
        std::string(along_v ? "[0, 1, 1]" : "[1, 0, 1]") + R"(, "intensity": [2, 2, 2]}],
      "shapes": [{"type": "quad", "corner": [-1, -1, 0], "u": [2, 0, 0], "v": [0, 2, 0], "material": "m"}]})";
    const Image img = render_in(dir, scene);
    EXPECT_NEAR(img.rgb[3 * (16 * 33 + 16)], expected, 1e-5 * expected) << (along_v ? "along v" : "along u");
  }
  std::filesystem::remove_all(dir);
}

TEST(NormalMaps, NormalAndBumpMapTogetherIsAnError) {
  const auto dir = test::temp_dir("maps-both");
  write_image(constant_image(4, 0.5f, 0.5f, 1.0f), (dir / "flat.exr").string());
  test::expect_load_error(dir, lit_quad(R"(, "normal_map": "flat.exr", "bump_map": "flat.exr")"),
                          "materials.m.bump_map: give a normal_map or a bump_map");
  std::filesystem::remove_all(dir);
}

// Two triangles of a quad whose u runs along -x: every corner's tangent is -x. A third
// triangle reuses the position (0, 0, 0) with another uv (a seam) and keeps its own, +z.
TEST(NormalMaps, VertexTangentsFollowTheUvDirection) {
  const auto tri = [](Vec3 a, Vec3 b, Vec3 c, float ua, float va, float ub, float vb, float uc, float vc) {
    MeshTriangle t{};
    t.p[0] = a, t.p[1] = b, t.p[2] = c;
    t.uv[0][0] = ua, t.uv[0][1] = va, t.uv[1][0] = ub, t.uv[1][1] = vb, t.uv[2][0] = uc, t.uv[2][1] = vc;
    t.has_uvs = true;
    return t;
  };
  std::vector<MeshTriangle> mesh = {tri({0, 0, 0}, {-1, 0, 0}, {-1, 0, 1}, 0, 0, 1, 0, 1, 1),
                                    tri({0, 0, 0}, {-1, 0, 1}, {0, 0, 1}, 0, 0, 1, 1, 0, 1),
                                    tri({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 5, 0, 6, 0, 5, 1)};
  compute_vertex_tangents(mesh);
  for (int t = 0; t < 2; ++t)
    for (int c = 0; c < 3; ++c) {
      ASSERT_TRUE(mesh[t].has_tangents);
      EXPECT_NEAR(mesh[t].tangent[c].x, -1.0f, 1e-6f) << t << "," << c;
      EXPECT_NEAR(mesh[t].tangent[c].z, 0.0f, 1e-6f) << t << "," << c;
    }
  EXPECT_NEAR(mesh[2].tangent[0].z, 1.0f, 1e-6f) << "the seam vertex keeps its own tangent";
}

}  // namespace
}  // namespace tracer
