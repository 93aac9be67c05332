// Degenerate and thin geometry. Zero-area triangles (collinear, duplicate or coincident
// corners) have no normal, so the loader leaves them out of meshes and refuses them as a
// lone `triangle`; the kernel's tests give finite answers on them anyway. Slivers and quads
// up to 1e7:1 are hit exactly where they should be, through every acceleration structure.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "kernel/accel/trace.h"
#include "kernel/geom/quad.h"
#include "kernel/geom/triangle_moller_trumbore.h"
#include "options/enum_names.h"
#include "render/render_cpu.h"
#include "scene/scene_types.h"
#include "test_util.h"

namespace tracer {
namespace {

using Stream = test::InputStream;

struct Triangle {
  Vec3 v0, v1, v2;
};

// Zero-area triangles as a mesh file has them: corners on a line with integer coordinates
// (the cross product is exactly 0), a repeated corner, and one point three times.
std::vector<Triangle> zero_area_triangles() {
  Stream s{17};
  const auto integer = [&](float range) { return std::floor((s.next() * 2.0f - 1.0f) * range); };
  std::vector<Triangle> tris;
  for (int k = 0; k < 3000; ++k) {
    const Vec3 p = {integer(8), integer(8), integer(8)}, d = {integer(4), integer(4), integer(4)};
    const Vec3 q = p + d;
    switch (k % 3) {
      case 0: tris.push_back({p, q, p + d * integer(3)}); break;
      case 1: tris.push_back({p, q, q}); break;
      default: tris.push_back({p, p, p}); break;
    }
  }
  return tris;
}

TEST(ExtremesDegenerate, ZeroAreaTrianglesAreNeverHitByTheWatertightTest) {
  Stream s{3};
  uint64_t rays = 0, watertight_hits = 0, moller_trumbore_hits = 0;
  for (const Triangle& tri : zero_area_triangles()) {
    ASSERT_EQ(length(cross(tri.v1 - tri.v0, tri.v2 - tri.v0)), 0.0f);
    for (int j = 0; j < 200; ++j) {
      // Aim at the corners and along the segment, from anywhere or straight down an axis.
      const float a = j % 4 == 0 ? 0.0f : j % 4 == 1 ? 1.0f : s.next();
      const Vec3 target = j % 8 == 2 ? tri.v2 : tri.v0 + (tri.v1 - tri.v0) * a;
      Vec3 origin = {s.next() * 40 - 20, s.next() * 40 - 20, s.next() * 40 - 20};
      if (j % 3 == 0)
        origin = target + Vec3{j % 9 == 0 ? 5.0f : 0.0f, j % 9 == 3 ? 5.0f : 0.0f, j % 9 == 6 ? 5.0f : 0.0f};
      if (!(length(target - origin) > 0.0f)) continue;
      const Ray ray = {origin, normalize(target - origin)};
      float t = 0, b0 = 0, b1 = 0, b2 = 0;
      ++rays;
      if (intersect_triangle(tri.v0, tri.v1, tri.v2, ray, make_ray_shear(ray.dir), 0.0f, kInfinity, t, b0, b1, b2)) {
        ++watertight_hits;
        EXPECT_TRUE(std::isfinite(t) && std::isfinite(b0) && std::isfinite(b1) && std::isfinite(b2));
      }
      if (intersect_triangle_moller_trumbore(tri.v0, tri.v1, tri.v2, ray, 0.0f, kInfinity, t, b0, b1, b2)) {
        ++moller_trumbore_hits;
        EXPECT_TRUE(std::isfinite(t) && std::isfinite(b0) && std::isfinite(b1) && std::isfinite(b2));
      }
    }
  }
  EXPECT_GT(rays, 500000u);
  EXPECT_EQ(watertight_hits, 0u) << "of " << rays << " rays";
  // Moller-Trumbore's determinant is rounding noise here, so it does report hits: this is
  // why the loader leaves such triangles out rather than trusting the ray test.
  EXPECT_GT(moller_trumbore_hits, 0u) << "of " << rays << " rays";
  std::printf("%llu rays at zero-area triangles: watertight %llu hits, Moller-Trumbore %llu hits\n",
              static_cast<unsigned long long>(rays), static_cast<unsigned long long>(watertight_hits),
              static_cast<unsigned long long>(moller_trumbore_hits));
}

// Rays aimed at the segments of zero-area mesh faces, through a loaded scene: no hit under
// either triangle test, since the loader left the faces out (with them kept,
// Moller-Trumbore hits some).
TEST(ExtremesDegenerate, ZeroAreaMeshFacesAreNeverHitInAScene) {
  std::string positions = "[-1, -1, -100], [1, -1, -100], [0, 1, -100]", indices = "[0, 1, 2]";
  const std::vector<Triangle> tris = zero_area_triangles();
  char buf[200];
  for (size_t i = 0; i < tris.size(); ++i) {
    for (const Vec3& v : {tris[i].v0, tris[i].v1, tris[i].v2}) {
      std::snprintf(buf, sizeof buf, ", [%g, %g, %g]", v.x, v.y, v.z);
      positions += buf;
    }
    const size_t k = 3 * i + 3;
    indices += ", [" + std::to_string(k) + ", " + std::to_string(k + 1) + ", " + std::to_string(k + 2) + "]";
  }
  for (const char* test : {"watertight", "moller-trumbore"}) {
    RenderOverrides ov;
    ov.triangle_test = parse_enum<TriangleTest>(test, "triangle_test");
    const Scene scene =
        test::scene_from(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40},
      "film": {"width": 8, "height": 8}, "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
      "shapes": [{"type": "mesh", "material": "m", "positions": [)" +
                             positions + "], \"indices\": [" + indices + "]}]}",
                         ov);
    EXPECT_EQ(scene.report.degenerate_triangles, tris.size());
    const SceneView view = scene.view();
    Stream s{23};
    int hits = 0;
    for (const Triangle& tri : tris) {
      for (int j = 0; j < 20; ++j) {
        const Vec3 target = tri.v0 + (tri.v1 - tri.v0) * s.next();
        const Vec3 origin = {s.next() * 40 - 20, s.next() * 40 - 20, s.next() * 40 - 20};
        hits += trace_closest(view, {origin, normalize(target - origin)}, 50.0f).prim != kNoHit;
      }
    }
    EXPECT_EQ(hits, 0) << test;
  }
}

// A lit floor and a mesh in front of the camera: one face with an area, [0, 1, 5], and
// (optionally) four without: [0, 1, 2] and [0, 2, 1] are collinear, [3, 4, 4] repeats a
// corner, [5, 5, 5] is a point.
std::string floor_scene(bool with_degenerate) {
  return std::string(R"({"format": "tracer-scene/1", "camera": {"from": [0, 0.5, 4], "to": [0, 0.5, 0], "vfov": 40},
    "film": {"width": 64, "height": 48}, "render": {"integrator": "path", "spp": 4, "sampler": "stochastic"},
    "background": {"type": "constant", "radiance": [0.2, 0.2, 0.2]},
    "materials": {"white": {"type": "lambert", "albedo": [0.8, 0.8, 0.8]}, "lamp": {"type": "emissive", "radiance": [4, 4, 4]}},
    "shapes": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "white"},
               {"type": "quad", "corner": [-0.5, 2, -0.5], "u": [1, 0, 0], "v": [0, 0, 1], "material": "lamp"},
               {"type": "mesh", "material": "white",
                "positions": [[-1, 0.2, 0], [0, 0.5, 0], [1, 0.8, 0], [-1, 1, 0.5], [1, 0.2, 0.5], [0.3, 0.6, 1]],
                "indices": [)") +
         (with_degenerate ? "[0, 1, 2], [3, 4, 4], [0, 1, 5], [5, 5, 5], [0, 2, 1]" : "[0, 1, 5]") + "]}]}";
}

TEST(ExtremesDegenerate, LoaderLeavesZeroAreaMeshTrianglesOut) {
  const Scene scene = test::scene_from(floor_scene(true));
  EXPECT_EQ(scene.report.degenerate_triangles, 4u);
  int triangles = 0;
  for (const Primitive& p : scene.primitives) triangles += p.kind == ShapeKind::Triangle;
  EXPECT_EQ(triangles, 1);
}

// The same image, bit for bit, with and without the zero-area faces in view, under both
// triangle tests and in both integrators; and no NaN anywhere.
TEST(ExtremesDegenerate, ZeroAreaTrianglesLeaveTheImageUnchanged) {
  for (const char* test : {"watertight", "moller-trumbore"}) {
    for (const char* integrator : {"path", "whitted"}) {
      RenderOverrides ov;
      ov.triangle_test = parse_enum<TriangleTest>(test, "triangle_test");
      ov.integrator = parse_enum<IntegratorKind>(integrator, "integrator");
      RenderStats with_stats, without_stats;
      const Image with = render_cpu(test::scene_from(floor_scene(true), ov), 0, with_stats);
      const Image without = render_cpu(test::scene_from(floor_scene(false), ov), 0, without_stats);
      EXPECT_EQ(with_stats.nonfinite_samples + without_stats.nonfinite_samples, 0u) << test << " " << integrator;
      EXPECT_TRUE(with.rgb == without.rgb) << test << " " << integrator;
    }
  }
}

// Slivers: the triangle (0,0,0) (1,0,0) (0.5,h,0) and the quad of sides 1 and h at x = 2,
// for aspect ratios 1/h up to 1e7. The thin side must be representable, so it lies along y
// near 0, and rays start within a few h of the plane y = 0 (from further away, the rounding
// of the ray's own origin and direction, 1e-7 of their size, exceeds the width). A target
// more than h/100 inside must be hit at its distance, one more than h/100 outside missed.
enum class Thin { Sliver, Quad, Outside, Edge };

Thin classify(Vec3 target, float h) {
  const float margin = 0.01f * h;
  if (target.x < 1.5f) {
    const float top = 2.0f * h * std::min(target.x, 1.0f - target.x);
    if (target.y > margin && target.y < top - margin) return Thin::Sliver;
    if (target.y < -margin || target.y > top + margin) return Thin::Outside;
    return Thin::Edge;
  }
  if (target.y > margin && target.y < h - margin) return Thin::Quad;
  if (target.y < -margin || target.y > h + margin) return Thin::Outside;
  return Thin::Edge;
}

std::vector<Ray> sliver_rays(float h, std::vector<Vec3>& targets) {
  Stream s{11};
  std::vector<Ray> rays;
  for (int i = 0; i < 40000; ++i) {
    const float x = (i % 2 == 0 ? 0.0f : 2.0f) + 0.01f + 0.98f * s.next();
    const Vec3 target = {x, h * (s.next() * 2.0f - 0.5f), 0.0f};
    const float side = i % 4 < 2 ? 1.0f : -1.0f;  // from the front and from behind
    const Vec3 origin = {s.next() * 5.0f - 1.0f, i % 3 == 0 ? 0.0f : h * (s.next() * 6.0f - 3.0f),
                         side * (0.5f + 2.5f * s.next())};
    if (classify(target, h) == Thin::Edge) continue;
    rays.push_back({origin, normalize(target - origin)});
    targets.push_back(target);
  }
  return rays;
}

TEST(ExtremesDegenerate, SliversAndThinQuadsAreHitWhereTheyShould) {
  for (const float h : {1e-3f, 1e-5f, 1e-7f}) {
    std::vector<Vec3> targets;
    const std::vector<Ray> rays = sliver_rays(h, targets);
    int inside = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
      const Ray& r = rays[i];
      const Thin expected = classify(targets[i], h);
      const double distance =
          std::sqrt(double(targets[i].x - r.origin.x) * (targets[i].x - r.origin.x) +
                    double(targets[i].y - r.origin.y) * (targets[i].y - r.origin.y) + double(r.origin.z) * r.origin.z);
      float t = 0, b0, b1, b2;
      const bool sliver = intersect_triangle({0, 0, 0}, {1, 0, 0}, {0.5f, h, 0}, r, make_ray_shear(r.dir), 0.0f,
                                             kInfinity, t, b0, b1, b2);
      if (sliver) {
        EXPECT_NEAR(t, distance, 1e-5 * distance) << "h " << h << " ray " << i;
      }
      float tm = 0;
      const bool sliver_mt =
          intersect_triangle_moller_trumbore({0, 0, 0}, {1, 0, 0}, {0.5f, h, 0}, r, 0.0f, kInfinity, tm, b0, b1, b2);
      float tq = 0, alpha, beta;
      const bool quad = intersect_quad({2, 0, 0}, {1, 0, 0}, {0, h, 0}, r, 0.0f, kInfinity, tq, alpha, beta);
      if (quad) {
        EXPECT_NEAR(tq, distance, 1e-5 * distance) << "h " << h << " ray " << i;
      }
      ASSERT_EQ(sliver, expected == Thin::Sliver)
          << "watertight, h " << h << " ray " << i << " o " << r.origin.x << " " << r.origin.y << " " << r.origin.z
          << " target " << targets[i].x << " " << targets[i].y / h << "h";
      ASSERT_EQ(sliver_mt, expected == Thin::Sliver) << "Moller-Trumbore, h " << h << " ray " << i;
      ASSERT_EQ(quad, expected == Thin::Quad) << "quad, h " << h << " ray " << i;
      inside += expected == Thin::Sliver || expected == Thin::Quad;
    }
    EXPECT_GT(inside, int(rays.size()) / 4) << "h " << h;  // both answers are tested
    EXPECT_GT(int(rays.size()) - inside, int(rays.size()) / 4) << "h " << h;
  }
}

// The same slivers in a scene: every acceleration structure (boxes of zero depth and 1e-7
// height) finds them exactly where the plain loop does.
TEST(ExtremesDegenerate, EveryStructureFindsTheSlivers) {
  for (const float h : {1e-3f, 1e-7f}) {
    char shapes[512];
    std::snprintf(shapes, sizeof shapes,
                  R"([{"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0.5, %.9g, 0]], "material": "m"},
      {"type": "quad", "corner": [2, 0, 0], "u": [1, 0, 0], "v": [0, %.9g, 0], "material": "m"}])",
                  h, h);
    std::vector<Vec3> targets;
    const std::vector<Ray> rays = sliver_rays(h, targets);
    for (const std::string& accel : accepted_scene_types().at("accel")) {
      RenderOverrides ov;
      ov.accel = parse_enum<AccelKind>(accel, "accel");
      const Scene scene = test::scene_from(
          std::string(
              R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40}, "film": {"width": 8, "height": 8},
        "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}}, "shapes": )") +
              shapes + "}",
          ov);
      const SceneView view = scene.view();
      for (size_t i = 0; i < rays.size(); ++i) {
        const Thin expected = classify(targets[i], h);
        const Hit hit = trace_closest(view, rays[i], kInfinity);
        const uint32_t want = expected == Thin::Sliver ? 0u : expected == Thin::Quad ? 1u : kNoHit;
        ASSERT_EQ(hit.prim, want) << accel << " h " << h << " ray " << i;
      }
    }
  }
}

// A ray whose origin or direction is not finite (a material's arithmetic gone to NaN: glass of
// a denormal ior refracted one) hits nothing on any structure. The 8-wide tree's box test,
// whose min and max drop a NaN, entered every child, the unused slots too (their child is the
// root), and the default structure crashed (SIGSEGV) on such a ray. Two clusters of eight
// triangles: the wide root holds two leaves and six unused slots.
TEST(ExtremesDegenerate, ARayThatIsNotFiniteHitsNothingOnAnyStructure) {
  std::string clusters;
  for (int i = 0; i < 16; ++i) {
    const float x = (i < 8 ? -2.0f : 2.0f) + 0.1f * static_cast<float>(i % 8), y = 0.1f * static_cast<float>(i % 8);
    char tri[160];
    std::snprintf(tri, sizeof tri,
                  R"(%s{"type": "triangle", "vertices": [[%g, %g, 0], [%g, %g, 0], [%g, %g, 0]], "material": "m"})",
                  i ? ", " : "", x - 0.5, y - 0.5, x + 0.5, y - 0.5, x, y + 0.5);
    clusters += tri;
  }
  const std::string text = R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 5], "to": [0, 0, 0], "vfov": 40},
    "film": {"width": 8, "height": 6}, "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "shapes": [)" + clusters +
                           "]}";
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = kInfinity;
  const Ray rays[] = {{{-2, 0, 3}, {nan, nan, nan}},
                      {{-2, 0, 3}, {0, nan, -1}},
                      {{nan, 0, 3}, {0, 0, -1}},
                      {{-2, 0, 3}, {0, inf, -1}},
                      {{inf, 0, 3}, {0, 0, -1}}};
  for (const std::string& accel : accepted_scene_types().at("accel")) {
    RenderOverrides ov;
    ov.accel = parse_enum<AccelKind>(accel, "accel");
    const Scene scene = test::scene_from(text, ov);
    const SceneView view = scene.view();
    if (accel == "bvh") {
      ASSERT_EQ(scene.wide_nodes.size(), 1u);
      EXPECT_EQ(scene.wide_nodes[0].lo[0][7], inf) << "an unused slot, which a NaN ray's box test enters";
    }
    ASSERT_NE(trace_closest(view, Ray{{-2, 0, 3}, {0, 0, -1}}, kInfinity).prim, kNoHit) << accel << ": aims at it";
    for (const Ray& ray : rays) {
      EXPECT_EQ(trace_closest(view, ray, kInfinity).prim, kNoHit) << accel;
      EXPECT_FALSE(trace_any(view, ray, kInfinity)) << accel;
    }
  }
}

}  // namespace
}  // namespace tracer
