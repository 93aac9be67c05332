// Closed-form answers for the features the other analytic tests do not reach: every shape
// (and every transform step) under the white furnace lands exactly where predicted and
// renders exactly its albedo; the gradient sky is its blend on y; the normals, albedo and
// depth views of a sphere; Blinn-Phong on a plane; a constant specular map scales the
// specular term; a height ramp tilts the normal by atan of its slope.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>

#include "image/image_io.h"
#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

struct Dir {
  double x, y, z;
};

Dir unit_dir(const Ray& r) { return {r.dir.x, r.dir.y, r.dir.z}; }

double hit_sphere(const Ray& r, Dir c, double radius) { return test::ray_sphere_distance(r, c.x, c.y, c.z, radius); }

// Rotation about z by `degrees` (the box's own transform below).
Dir rotate_z(Dir p, double degrees) {
  const double a = degrees * M_PI / 180.0;
  return {p.x * std::cos(a) - p.y * std::sin(a), p.x * std::sin(a) + p.y * std::cos(a), p.z};
}

// Ray against the box [lo, hi] rotated about z: the slab test in the box's frame.
bool hit_rotated_box(const Ray& r, Dir lo, Dir hi, double degrees) {
  const Dir o = rotate_z({r.origin.x, r.origin.y, r.origin.z}, -degrees), d = rotate_z(unit_dir(r), -degrees);
  double t0 = -1e30, t1 = 1e30;
  const double os[3] = {o.x, o.y, o.z}, ds[3] = {d.x, d.y, d.z}, los[3] = {lo.x, lo.y, lo.z},
               his[3] = {hi.x, hi.y, hi.z};
  for (int k = 0; k < 3; ++k) {
    if (ds[k] == 0) {
      if (os[k] < los[k] || os[k] > his[k]) return false;
      continue;
    }
    double a = (los[k] - os[k]) / ds[k], b = (his[k] - os[k]) / ds[k];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a), t1 = std::min(t1, b);
  }
  return t0 <= t1 && t1 > 0;
}

// Whether a predicate holds for rays through a pixel's centre and eight neighbours a
// hundredth of a pixel away: a pixel is judged only where all nine agree.
int judged(const Scene& scene, float fx, float fy, const std::function<bool(const Ray&)>& hit) {
  int hits = 0;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) hits += hit(camera_ray(scene.camera, fx + 0.01f * i, fy + 0.01f * j, 0.0f, 0.0f));
  return hits == 9 ? 1 : hits == 0 ? 0 : -1;
}

// The white furnace again, shape by shape: under a sky of 1 a convex Lambert body of
// albedo 0.6 scatters each camera ray once and the ray escapes, so every pixel is exactly
// 0.6 or 1. Each shape is moved by transform steps, and its pixels are where the moved
// shape is, found by intersecting it in double precision.
TEST(ClosedForms, EveryShapeAndTransformLandsWhereItShouldWithItsAlbedo) {
  const auto inside_triangle = [](const Ray& r, Dir a, Dir b, Dir c) {  // in the plane z = 0
    if (r.dir.z == 0.0f) return false;
    const double t = -double(r.origin.z) / r.dir.z;
    if (t <= 0) return false;
    const double px = r.origin.x + t * r.dir.x, py = r.origin.y + t * r.dir.y;
    const auto edge = [&](Dir p, Dir q) { return (q.x - p.x) * (py - p.y) - (q.y - p.y) * (px - p.x); };
    const double e0 = edge(a, b), e1 = edge(b, c), e2 = edge(c, a);
    return (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
  };
  const std::vector<std::pair<std::string, std::function<bool(const Ray&)>>> shapes = {
      {R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "transform": [{"scale": 0.5}, {"translate": [0.3, -0.2, 0]}]})",
       [](const Ray& r) {
         return hit_sphere(r, {0.3, -0.2, 0}, 0.5) > 0;
       }},
      {R"({"type": "box", "min": [-0.6, -0.3, -0.3], "max": [0.6, 0.3, 0.3], "transform": [{"rotate": {"axis": [0, 0, 1], "degrees": 30}}]})",
       [](const Ray& r) {
         return hit_rotated_box(r, {-0.6, -0.3, -0.3}, {0.6, 0.3, 0.3}, 30);
       }},
      {R"({"type": "box", "min": [-0.5, -0.25, -0.25], "max": [0.5, 0.25, 0.25], "transform": [{"rotate_xyz": [0, 0, -40]}]})",
       [](const Ray& r) {
         return hit_rotated_box(r, {-0.5, -0.25, -0.25}, {0.5, 0.25, 0.25}, -40);
       }},
      {R"({"type": "quad", "corner": [-0.5, -0.4, 0], "u": [1, 0, 0], "v": [0, 0.8, 0]})",
       [=](const Ray& r) {
         return inside_triangle(r, {-0.5, -0.4, 0}, {0.5, -0.4, 0}, {0.5, 0.4, 0}) ||
                inside_triangle(r, {-0.5, -0.4, 0}, {0.5, 0.4, 0}, {-0.5, 0.4, 0});
       }},
      {R"({"type": "triangle", "vertices": [[-0.6, -0.5, 0], [0.7, -0.3, 0], [0, 0.6, 0]]})",
       [=](const Ray& r) {
         return inside_triangle(r, {-0.6, -0.5, 0}, {0.7, -0.3, 0}, {0, 0.6, 0});
       }},
      {R"({"type": "mesh", "positions": [[-0.6, -0.5, 0], [0.6, -0.5, 0], [0.6, 0.5, 0], [-0.6, 0.5, 0], [0, 0, 0.3]],
           "indices": [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]})",  // a pyramid seen from above: its outline is the
                                                                        // base
       [=](const Ray& r) {
         return inside_triangle(r, {-0.6, -0.5, 0}, {0.6, -0.5, 0}, {0.6, 0.5, 0}) ||
                inside_triangle(r, {-0.6, -0.5, 0}, {0.6, 0.5, 0}, {-0.6, 0.5, 0});
       }},
      {R"({"type": "plane", "point": [0, -0.5, 0], "normal": [0, 1, 0]})",  // below the horizon
       [](const Ray& r) { return r.dir.y < 0.0f; }}};
  for (const auto& [shape, hit] : shapes) {
    std::string json = shape;
    json.insert(json.size() - 1, R"(, "material": "m")");
    const Scene scene =
        test::scene_from(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40},
      "film": {"width": 48, "height": 48}, "render": {"integrator": "path", "spp": 1, "sampler": "center", "max_depth": 8},
      "background": {"type": "constant", "radiance": [1, 1, 1]},
      "materials": {"m": {"type": "lambert", "albedo": [0.6, 0.6, 0.6]}}, "shapes": [)" +
                         json + "]}");
    RenderStats stats;
    const Image img = render_cpu(scene, 0, stats);
    int on = 0, off = 0;
    for (uint32_t y = 0; y < 48; ++y)
      for (uint32_t x = 0; x < 48; ++x) {
        const float v = img.rgb[3 * (y * 48 + x)];
        EXPECT_TRUE(v == 1.0f || std::abs(v - 0.6f) <= 1e-6f) << shape << ": " << v << " at " << x << ", " << y;
        const int expected = judged(scene, x + 0.5f, y + 0.5f, hit);
        if (expected < 0) continue;
        EXPECT_EQ(v != 1.0f, expected == 1) << shape << " at " << x << ", " << y;
        (expected ? on : off) += 1;
      }
    EXPECT_GT(on, 100) << shape;
    EXPECT_GT(off, 100) << shape;
  }
}

// The gradient sky blends horizon and zenith on the direction's y (0 at and below the
// horizon): every pixel of an empty scene, in both integrators.
TEST(ClosedForms, GradientSkyIsTheBlendOnY) {
  for (const char* integrator : {"path", "whitted"}) {
    const Scene scene = test::scene_from(
        std::string(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 0], "to": [0, 0.3, -1], "vfov": 90},
      "film": {"width": 32, "height": 32}, "render": {"integrator": ")") +
        integrator + R"(", "spp": 1, "sampler": "center"},
      "background": {"type": "gradient", "zenith": [0.2, 0.4, 1], "horizon": [1, 0.9, 0.8]}, "materials": {}, "shapes": []})");
    RenderStats stats;
    const Image img = render_cpu(scene, 0, stats);
    const double zenith[3] = {0.2, 0.4, 1}, horizon[3] = {1, 0.9, 0.8};
    int below = 0;
    for (uint32_t y = 0; y < 32; ++y)
      for (uint32_t x = 0; x < 32; ++x) {
        const Ray r = camera_ray(scene.camera, x + 0.5f, y + 0.5f, 0.0f, 0.0f);
        const double t = std::max(0.0, double(r.dir.y));
        below += t == 0;
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(img.rgb[3 * (y * 32 + x) + c], horizon[c] * (1 - t) + zenith[c] * t, 1e-6)
              << integrator << " " << x << ", " << y;
      }
    EXPECT_GT(below, 32) << "the view reaches below the horizon";
  }
}

// The debug views of a unit sphere at (0.2, -0.1, 0): the normals view is (n + 1) / 2, the
// depth view the distance along the unit camera ray, the albedo view the material's colour;
// a miss is 0 in each.
TEST(ClosedForms, DebugViewsOfASphere) {
  const Dir centre = {0.2, -0.1, 0};
  for (const char* view : {"normals", "depth", "albedo"}) {
    const Scene scene = test::scene_from(
        std::string(R"({"format": "tracer-scene/1", "camera": {"from": [0.5, 1, 4], "to": [0, 0, 0], "vfov": 40},
      "film": {"width": 40, "height": 40}, "render": {"integrator": ")") +
        view + R"(", "spp": 1, "sampler": "center"},
      "materials": {"m": {"type": "lambert", "albedo": [0.3, 0.5, 0.7]}},
      "shapes": [{"type": "sphere", "center": [0.2, -0.1, 0], "radius": 1, "material": "m"}]})");
    RenderStats stats;
    const Image img = render_cpu(scene, 0, stats);
    int hits = 0;
    double worst = 0;  // relative above 1, absolute below
    for (uint32_t y = 0; y < 40; ++y)
      for (uint32_t x = 0; x < 40; ++x) {
        const Ray r = camera_ray(scene.camera, x + 0.5f, y + 0.5f, 0.0f, 0.0f);
        const double t = hit_sphere(r, centre, 1.0);
        const float* px = &img.rgb[3 * (y * 40 + x)];
        if (t < 0) {
          EXPECT_TRUE(px[0] == 0 && px[1] == 0 && px[2] == 0) << view << " " << x << ", " << y;
          continue;
        }
        ++hits;
        const Dir d = unit_dir(r);
        const double n[3] = {r.origin.x + t * d.x - centre.x, r.origin.y + t * d.y - centre.y,
                             r.origin.z + t * d.z - centre.z};
        const double albedo[3] = {0.3f, 0.5f, 0.7f};  // as the scene's floats
        for (int c = 0; c < 3; ++c) {
          const double expected = std::string(view) == "normals" ? (n[c] + 1) / 2
                                  : std::string(view) == "depth" ? t
                                                                 : albedo[c];
          worst = std::max(worst, std::abs(px[c] - expected) / std::max(1.0, expected));
        }
      }
    EXPECT_GT(hits, 300) << view;
    std::printf("%s view: largest error %.3g\n", view, worst);
    // The float hit point of a sphere loses accuracy towards the silhouette (t from a
    // difference of nearly equal roots), which the normal inherits: 1e-4 for both.
    EXPECT_LE(worst, std::string(view) == "albedo" ? 0.0 : 1e-4) << view;
  }
}

// Whitted's Phong material on a plane under a point light, pixel by pixel:
// ka ambient + (kd cos + ks max(n.h, 0)^shininess) I / d^2 with h the half vector.
TEST(ClosedForms, PhongPlaneIsBlinnPhong) {
  const Scene scene =
      test::scene_from(R"({"format": "tracer-scene/1", "camera": {"from": [0.2, 3, 4], "to": [0, 0, 0], "vfov": 50},
    "film": {"width": 64, "height": 48}, "render": {"integrator": "whitted", "spp": 1, "sampler": "center", "max_depth": 0},
    "ambient": [0.1, 0.1, 0.1],
    "materials": {"m": {"type": "phong", "ambient": [0.2, 0.3, 0.4], "diffuse": [0.5, 0.4, 0.3], "specular": [0.4, 0.4, 0.4], "shininess": 30}},
    "lights": [{"type": "point", "position": [0.3, 2, -0.2], "intensity": [3, 4, 5]}],
    "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "m"}]})");
  RenderStats stats;
  const Image img = render_cpu(scene, 0, stats);
  const double ka[3] = {0.2, 0.3, 0.4}, kd[3] = {0.5, 0.4, 0.3}, ks = 0.4, I[3] = {3, 4, 5}, L[3] = {0.3, 2, -0.2};
  double worst = 0;
  int lit = 0;
  for (uint32_t y = 0; y < 48; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      const Ray r = camera_ray(scene.camera, x + 0.5f, y + 0.5f, 0.0f, 0.0f);
      if (!(r.dir.y < 0.0f)) continue;
      const Dir d = unit_dir(r);
      const double t = -double(r.origin.y) / d.y;
      const double p[3] = {r.origin.x + t * d.x, 0, r.origin.z + t * d.z};
      const double l[3] = {L[0] - p[0], L[1] - p[1], L[2] - p[2]};
      const double d2 = l[0] * l[0] + l[1] * l[1] + l[2] * l[2], dist = std::sqrt(d2);
      const double cos = l[1] / dist;
      const double h[3] = {l[0] / dist - d.x, l[1] / dist - d.y, l[2] / dist - d.z};
      const double cos_h = h[1] / std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
      for (int c = 0; c < 3; ++c) {
        const double expected = ka[c] * 0.1 + (kd[c] * cos + ks * std::pow(cos_h, 30)) * I[c] / d2;
        const double rel = std::abs(img.rgb[3 * (y * 64 + x) + c] - expected) / expected;
        worst = std::max(worst, rel);
        EXPECT_LE(rel, 1e-5) << x << ", " << y << " channel " << c;
      }
      ++lit;
    }
  EXPECT_GT(lit, 1000);
  std::printf("Blinn-Phong plane: largest relative error %.3g\n", worst);
}

// A w x h grey image whose column x has the value value_of_column(x).
Image column_image(uint32_t w, uint32_t h, const std::function<float(uint32_t)>& value_of_column) {
  return test::image_from(w, h, [&](uint32_t x, uint32_t) { return Vec3{1, 1, 1} * value_of_column(x); });
}

using test::render_in;

std::string lit_quad(const std::string& material) {
  return R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 2], "to": [0, 0, 0], "vfov": 60},
    "film": {"width": 33, "height": 33}, "render": {"integrator": "whitted", "sampler": "center", "max_depth": 1},
    "materials": {"m": )" +
         material + R"(},
    "lights": [{"type": "point", "position": [0.7, 0.4, 1.5], "intensity": [3, 3, 3]}],
    "shapes": [{"type": "quad", "corner": [-1, -1, 0], "u": [2, 0, 0], "v": [0, 2, 0], "material": "m"}]})";
}

// A specular map of 0.5 everywhere halves ks: the image equals, bit for bit, the one with
// ks given as half (a product by 0.5 is exact).
TEST(ClosedForms, ConstantSpecularMapScalesTheSpecularTerm) {
  const auto dir = test::temp_dir("closed-specular-map");
  write_image(column_image(4, 4, [](uint32_t) { return 0.5f; }), (dir / "half.exr").string());
  const Image mapped = render_in(
      dir,
      lit_quad(
          R"({"type": "phong", "diffuse": [0.5, 0.5, 0.5], "specular": [0.6, 0.6, 0.6], "shininess": 20, "specular_map": "half.exr"})"));
  const Image halved = render_in(
      dir, lit_quad(R"({"type": "phong", "diffuse": [0.5, 0.5, 0.5], "specular": [0.3, 0.3, 0.3], "shininess": 20})"));
  const Image full = render_in(
      dir, lit_quad(R"({"type": "phong", "diffuse": [0.5, 0.5, 0.5], "specular": [0.6, 0.6, 0.6], "shininess": 20})"));
  EXPECT_EQ(std::memcmp(mapped.rgb.data(), halved.rgb.data(), mapped.rgb.size() * sizeof(float)), 0);
  EXPECT_NE(std::memcmp(mapped.rgb.data(), full.rgb.data(), mapped.rgb.size() * sizeof(float)), 0);
  std::filesystem::remove_all(dir);
}

// A height map rising g per texel along u: central differences one texel apart give the
// local normal (-g, 0, 1), tilted by atan(g) against the quad's u (+x). With the light at
// (1, 0, 1) from the centre point the path tracer's direct light there is
// albedo I cos / (pi d^2) with cos = (1 - g) / (sqrt 2 sqrt(1 + g^2)). The same ramp along v
// (rising towards the image's top row) tilts the normal to (0, -g, 1), against the quad's v
// (+y, the bitangent), and gives the same cosine with the light at (0, 1, 1).
TEST(ClosedForms, HeightRampTiltsTheNormalByItsSlope) {
  const auto dir = test::temp_dir("closed-bump-ramp");
  const float g = 0.25f;
  const double cos = (1.0 - g) / (std::sqrt(2.0) * std::sqrt(1.0 + double(g) * g));
  const double expected = 0.5 / M_PI * 2.0 * cos / 2.0;  // d^2 = 2
  for (const bool along_v : {false, true}) {
    const Image ramp = test::image_from(8, 8, [&](uint32_t x, uint32_t y) {
      const float h = g * static_cast<float>(along_v ? 7 - y : x);
      return Vec3{h, h, h};
    });
    write_image(ramp, (dir / "ramp.exr").string());
    const Image img =
        render_in(dir, R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 2], "to": [0, 0, 0], "vfov": 60},
      "film": {"width": 33, "height": 33}, "render": {"integrator": "path", "sampler": "center", "max_depth": 1},
      "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5], "bump_map": "ramp.exr"}},
      "lights": [{"type": "point", "position": )" +
                           std::string(along_v ? "[0, 1, 1]" : "[1, 0, 1]") + R"(, "intensity": [2, 2, 2]}],
      "shapes": [{"type": "quad", "corner": [-1, -1, 0], "u": [2, 0, 0], "v": [0, 2, 0], "material": "m"}]})");
    EXPECT_NEAR(img.rgb[3 * (16 * 33 + 16)], expected, 1e-5 * expected) << (along_v ? "along v" : "along u");
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tracer
