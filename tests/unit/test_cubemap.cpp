// Cube-map backgrounds: each direction picks the face and (u, v) of the documented
// convention, neighbouring faces meet without cracks, a constant-colour cube map renders
// exactly like the constant background when only BSDF rays find it (sky sampling off), and
// bad faces are errors naming the key.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cstring>

#include "image/image_io.h"
#include "io/input_error.h"
#include "kernel/light/light.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

TEST(Cubemap, FaceAndCoordinatesOfTheAxesAndEdges) {
  float u, v;
  const struct {
    Vec3 d;
    uint32_t face;
    float u, v;
  } cases[] = {{{1, 0, 0}, 0, 0.5f, 0.5f},     {{-1, 0, 0}, 1, 0.5f, 0.5f},     {{0, 1, 0}, 2, 0.5f, 0.5f},
               {{0, -1, 0}, 3, 0.5f, 0.5f},    {{0, 0, 1}, 4, 0.5f, 0.5f},      {{0, 0, -1}, 5, 0.5f, 0.5f},
               {{1, 0.5f, 0}, 0, 0.5f, 0.75f}, {{0.5f, 0, -1}, 5, 0.75f, 0.5f},  // up on +x; right on -z is +x
               {{0, 1, -0.5f}, 2, 0.5f, 0.25f}};                                 // on +y, -z is down the image
  for (const auto& c : cases) {
    EXPECT_EQ(cube_face(c.d, u, v), c.face) << c.d.x << "," << c.d.y << "," << c.d.z;
    EXPECT_EQ(u, c.u) << c.d.x << "," << c.d.y << "," << c.d.z;
    EXPECT_EQ(v, c.v) << c.d.x << "," << c.d.y << "," << c.d.z;
  }
}

std::string scene_with(const std::string& background) {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 1, 3], "to": [0, 0.5, 0], "vfov": 80},
    "film": {"width": 48, "height": 32}, "render": {"integrator": "path", "spp": 4, "max_depth": 3, "sky_sampling": false},
    "background": )" +
         background + R"(, "materials": {"m": {"type": "metal", "albedo": [0.9, 0.9, 0.9], "roughness": 0.3},
    "d": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "shapes": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "m"},
               {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "d"}]})";
}

TEST(Cubemap, ConstantCubeMapEqualsTheConstantBackgroundBitForBit) {
  const auto dir = test::temp_dir("cube-constant");
  const std::string faces = test::write_cube_faces(dir, 8, [](int, int, int) { return Vec3{0.3f, 0.6f, 0.9f}; });
  const Scene cube =
      load_scene_text(scene_with(R"({"type": "cubemap", "faces": [)" + faces + "]}"), (dir / "s.json").string());
  const Scene constant =
      load_scene_text(scene_with(R"({"type": "constant", "radiance": [0.3, 0.6, 0.9]})"), (dir / "s.json").string());
  RenderStats s1, s2;
  const Image a = render_cpu(cube, 1, s1), b = render_cpu(constant, 1, s2);
  EXPECT_EQ(std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)), 0);
  std::filesystem::remove_all(dir);
}

// Faces painted with 0.5 + 0.5 d for the direction d of each texel centre, through the
// inverse of cube_face's map (d = f + (2u - 1) R + (2v - 1) U).
std::string write_direction_faces(const std::filesystem::path& dir, int n) {
  const Vec3 f[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const Vec3 up[6] = {{0, 1, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {0, 1, 0}};
  return test::write_cube_faces(dir, n, [&](int i, int x, int y) {
    const Vec3 right = cross(f[i], up[i]);
    const float u = (x + 0.5f) / n, v = 1.0f - (y + 0.5f) / n;
    return normalize(f[i] + right * (2 * u - 1) + up[i] * (2 * v - 1)) * 0.5f + Vec3{0.5f, 0.5f, 0.5f};
  });
}

// Every direction sees the colour of its own direction, to within the texel resolution:
// faces are oriented as documented and meet without cracks along all twelve edges.
TEST(Cubemap, FacesAreOrientedAndMeetWithoutCracks) {
  const auto dir = test::temp_dir("cube-seams");
  const std::string faces = write_direction_faces(dir, 64);
  const Scene scene =
      load_scene_text(scene_with(R"({"type": "cubemap", "faces": [)" + faces + "]}"), (dir / "s.json").string());
  const SceneView view = scene.view();
  int checked = 0;
  float worst = 0.0f;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      if (a == b) continue;
      for (const float sa : {-1.0f, 1.0f})
        for (const float sb : {-1.0f, 1.0f})
          for (const float t : {-0.6f, 0.0f, 0.6f})
            for (const float e : {0.9999f, 1.0f, 1.0001f}) {  // just inside, on and just past the edge
              Vec3 d{0, 0, 0};
              d[a] = sa, d[b] = sb * e, d[3 - a - b] = t;
              d = normalize(d);
              const Vec3 c = background_radiance(view, d), expected = d * 0.5f + Vec3{0.5f, 0.5f, 0.5f};
              worst = std::max(worst, max_component(max_of(c - expected, expected - c)));
              ++checked;
            }
    }
  EXPECT_LT(worst, 0.02f) << "a 64-texel face resolves directions to about 1/64 of a face";
  EXPECT_EQ(checked, 216);
  std::filesystem::remove_all(dir);
}

TEST(Cubemap, BadFacesAreErrors) {
  const auto dir = test::temp_dir("cube-bad");
  test::write_cube_faces(dir, 4, [](int, int, int) { return Vec3{0, 0, 0}; });
  write_image(Image{4, 2, std::vector<float>(24, 0.0f)}, (dir / "wide.exr").string());
  write_image(Image{8, 8, std::vector<float>(192, 0.0f)}, (dir / "big.exr").string());
  const struct {
    std::string background, expected;
  } cases[] = {
      {R"({"type": "cubemap", "faces": ["f0.exr"]})", "background.faces: expected six image files"},
      {R"({"type": "cubemap", "faces": ["f0.exr", "f1.exr", "wide.exr", "f3.exr", "f4.exr", "f5.exr"]})",
       "background.faces[2]: cube faces must be square"},
      {R"({"type": "cubemap", "faces": ["f0.exr", "f1.exr", "f2.exr", "big.exr", "f4.exr", "f5.exr"]})",
       "background.faces[3]: cube faces must all be the same size"},
      {R"({"type": "cubemap", "faces": ["f0.exr", "f1.exr", "f2.exr", "f3.exr", "f4.exr", "gone.exr"]})",
       "background.faces[5]: image"},
  };
  for (const auto& k : cases) test::expect_load_error(dir, scene_with(k.background), k.expected);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tracer
