// Ray/shape intersections at known t, normal and uv; interpolated vertex normals; watertight
// shared edges; every acceleration structure returns the same hit as brute force.
#include <gtest/gtest.h>

#include <array>
#include <random>
#include <string>
#include <vector>

#include "accel/acceleration.h"
#include "accel/bounds.h"
#include "kernel/geom/ray_offset.h"
#include "kernel/shading/optics.h"
#include "kernel/shading/surface.h"
#include "options/enum_names.h"
#include "test_util.h"

using namespace tracer;

TEST(Sphere, HitAtKnownDistanceAndNormal) {
  float t;
  const Ray r = {{0, 0, 5}, {0, 0, -1}};
  ASSERT_TRUE(intersect_sphere({0, 0, 0}, 1.0f, r, 0.0f, kInfinity, t));
  EXPECT_EQ(t, 4.0f);
  const Ray inside = {{0, 0, 0}, {1, 0, 0}};
  ASSERT_TRUE(intersect_sphere({0, 0, 0}, 2.0f, inside, 0.0f, kInfinity, t));
  EXPECT_EQ(t, 2.0f);
  EXPECT_FALSE(intersect_sphere({0, 0, 0}, 1.0f, {{0, 2, 5}, {0, 0, -1}}, 0.0f, kInfinity, t));
  EXPECT_FALSE(intersect_sphere({0, 0, 0}, 1.0f, r, 0.0f, 3.9f, t));  // beyond tmax
}

TEST(Triangle, HitAtKnownDistanceAndBarycentrics) {
  const Vec3 v0 = {0, 0, 0}, v1 = {1, 0, 0}, v2 = {0, 1, 0};
  const Ray r = {{0.25f, 0.5f, 2.0f}, {0, 0, -1}};
  float t, b0, b1, b2;
  ASSERT_TRUE(intersect_triangle(v0, v1, v2, r, make_ray_shear(r.dir), 0.0f, kInfinity, t, b0, b1, b2));
  EXPECT_EQ(t, 2.0f);
  EXPECT_FLOAT_EQ(b1, 0.25f);
  EXPECT_FLOAT_EQ(b2, 0.5f);
  EXPECT_FLOAT_EQ(b0, 0.25f);
  const Ray miss = {{0.75f, 0.5f, 2.0f}, {0, 0, -1}};
  EXPECT_FALSE(intersect_triangle(v0, v1, v2, miss, make_ray_shear(miss.dir), 0.0f, kInfinity, t, b0, b1, b2));
}

TEST(Triangle, DegenerateTrianglesNeverHit) {
  const Ray r = {{0.5f, 0.0f, 2.0f}, {0, 0, -1}};
  float t, b0, b1, b2;
  const RayShear s = make_ray_shear(r.dir);
  EXPECT_FALSE(intersect_triangle({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, r, s, 0.0f, kInfinity, t, b0, b1, b2));
  EXPECT_FALSE(intersect_triangle({0, 0, 0}, {0, 0, 0}, {1, 1, 0}, r, s, 0.0f, kInfinity, t, b0, b1, b2));
  EXPECT_FALSE(intersect_triangle({0.5f, 0, 0}, {0.5f, 0, 0}, {0.5f, 0, 0}, r, s, 0.0f, kInfinity, t, b0, b1, b2));
}

// Rays through the shared edge and vertices of two triangles always hit at least one of
// them: the watertight test has no cracks.
TEST(Triangle, SharedEdgeIsWatertight) {
  const Vec3 a = {-1, -1, 0}, b = {1, -1, 0}, c = {1, 1, 0}, d = {-1, 1, 0};
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f), o(-3.0f, 3.0f);
  for (int i = 0; i < 200000; ++i) {
    const float s = u(rng);
    const Vec3 on_edge = a + (c - a) * (0.5f * (s + 1.0f));  // the diagonal a-c
    const Vec3 origin = {o(rng), o(rng), 1.0f + std::abs(o(rng))};
    const Ray r = {origin, normalize(on_edge - origin)};
    const RayShear sh = make_ray_shear(r.dir);
    float t, b0, b1, b2;
    const bool h1 = intersect_triangle(a, b, c, r, sh, 0.0f, kInfinity, t, b0, b1, b2);
    const bool h2 = intersect_triangle(a, c, d, r, sh, 0.0f, kInfinity, t, b0, b1, b2);
    ASSERT_TRUE(h1 || h2) << "ray " << i << " escaped through the shared edge";
  }
}

TEST(Quad, HitGivesPlanarCoordinates) {
  float t, alpha, beta;
  const Ray r = {{0.5f, 0.25f, 1.0f}, {0, 0, -1}};
  ASSERT_TRUE(intersect_quad({0, 0, 0}, {2, 0, 0}, {0, 1, 0}, r, 0.0f, kInfinity, t, alpha, beta));
  EXPECT_EQ(t, 1.0f);
  EXPECT_EQ(alpha, 0.25f);
  EXPECT_EQ(beta, 0.25f);
  EXPECT_FALSE(intersect_quad({0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {{0.5f, 1.5f, 1.0f}, {0, 0, -1}}, 0.0f, kInfinity, t,
                              alpha, beta));
}

TEST(Plane, HitFromEitherSide) {
  float t;
  EXPECT_TRUE(intersect_plane({0, 0, 0}, {0, 1, 0}, {{0, 2, 0}, {0, -1, 0}}, 0.0f, kInfinity, t));
  EXPECT_EQ(t, 2.0f);
  EXPECT_TRUE(intersect_plane({0, 0, 0}, {0, 1, 0}, {{0, -3, 0}, {0, 1, 0}}, 0.0f, kInfinity, t));
  EXPECT_EQ(t, 3.0f);
  EXPECT_FALSE(intersect_plane({0, 0, 0}, {0, 1, 0}, {{0, 1, 0}, {1, 0, 0}}, 0.0f, kInfinity, t));
}

namespace {

std::string one_shape_scene(const std::string& shape) {
  return R"({"format": "tracer-scene/1",
    "camera": {"from": [0, 0, 10], "to": [0, 0, 0], "vfov": 40},
    "film": {"width": 8, "height": 8},
    "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "shapes": [)" +
         shape + "]}";
}

// Fires rays at a scene holding one convex or flat shape, reflects them off the hit
// (origin offset as the integrator does) and counts reflected rays that hit anything:
// each of them is a self-intersection.
int self_hits(const Scene& scene, Vec3 aim_center, float aim_radius) {
  const SceneView view = scene.view();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int bad = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 target = aim_center + Vec3{u(rng), u(rng), u(rng)} * aim_radius;
    const Vec3 origin = aim_center + normalize(Vec3{u(rng), u(rng), 1.5f}) * (aim_radius * 40.0f);
    const Ray ray = {origin, normalize(target - origin)};
    const Hit hit = trace_closest(view, ray, kInfinity);
    if (hit.prim == kNoHit) continue;
    const Surface s = surface_at(view, ray, hit);
    const Vec3 n = dot(ray.dir, s.ng) < 0.0f ? s.ng : -s.ng;
    const Vec3 d = reflect(ray.dir, n);
    const Ray out = {offset_ray_origin(s.p, s.ng, d, 1.0f), d};
    const Hit again = trace_closest(view, out, kInfinity);
    if (again.prim != kNoHit) ++bad;
  }
  return bad;
}

}  // namespace

// Phong's normal interpolation (Phong 1975): a triangle inscribed in the unit sphere whose
// vertex normals are its vertices' positions has, at a hit with barycentrics b, the shading
// normal b0 n0 + b1 n1 + b2 n2 = b0 v0 + b1 v1 + b2 v2 = p, so it points from the centre
// through the hit point. Each weight must go with its own vertex's normal.
TEST(Triangle, VertexNormalsOfAnInscribedMeshPointFromTheCentreThroughTheHit) {
  const Scene scene = test::scene_from(one_shape_scene(
      R"({"type": "mesh", "file": ")" + test::source_path("scenes/models/icosahedron.obj") + R"(", "material": "m"})"));
  const SceneView view = scene.view();
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> aim(-0.45f, 0.45f);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 origin = {0.0f, 0.0f, 5.0f}, target = {aim(rng), aim(rng), aim(rng)};
    const Ray ray = {origin, normalize(target - origin)};
    const Hit hit = trace_closest(view, ray, kInfinity);
    ASSERT_NE(hit.prim, kNoHit) << "ray " << i;  // every aim point lies within the inradius, 0.79
    const Surface s = surface_at(view, ray, hit);
    const Vec3 radial = normalize(s.p);
    ASSERT_NEAR(s.ns.x, radial.x, 1e-5f) << "ray " << i;
    ASSERT_NEAR(s.ns.y, radial.y, 1e-5f) << "ray " << i;
    ASSERT_NEAR(s.ns.z, radial.z, 1e-5f) << "ray " << i;
    ++hits;
  }
  EXPECT_EQ(hits, 20000);
}

TEST(Shapes, NoSelfIntersectionAtLargeCoordinates) {
  const Scene sphere = test::scene_from(
      one_shape_scene(R"({"type": "sphere", "center": [300, 200, 500], "radius": 90, "material": "m"})"));
  EXPECT_EQ(self_hits(sphere, {300, 200, 500}, 90.0f), 0);
  const Scene quad = test::scene_from(one_shape_scene(
      R"({"type": "quad", "corner": [0, 0, 559.2], "u": [556, 0, 0], "v": [0, 548.8, 0], "material": "m"})"));
  EXPECT_EQ(self_hits(quad, {278, 274, 559.2f}, 270.0f), 0);
  const Scene plane = test::scene_from(
      one_shape_scene(R"({"type": "plane", "point": [0, 0, 0], "normal": [1, 0, 0], "material": "m"})"));
  EXPECT_EQ(self_hits(plane, {0, 274, 300}, 270.0f), 0);
  const Scene tris = test::scene_from(one_shape_scene(R"({"type": "mesh", "material": "m",
      "positions": [[0, 0, 559.2], [0, 0, 0], [0, 548.8, 0], [0, 548.8, 559.2]], "indices": [[0, 1, 2], [0, 2, 3]]})"));
  EXPECT_EQ(self_hits(tris, {0, 274, 280}, 270.0f), 0);
}

namespace {

// A soup of spheres and triangles, with a dense cluster of small triangles so leaves hold
// several triangle blocks and primitives straddle many kd-tree leaves and grid cells.
struct Soup {
  std::string shapes;
  std::vector<std::array<Vec3, 3>> triangles;
};

Soup soup_with_a_cluster(std::mt19937& rng) {
  std::uniform_real_distribution<float> p(-5.0f, 5.0f), r(0.05f, 0.6f), e(-0.8f, 0.8f), cluster(-0.7f, 0.7f),
      small(-0.15f, 0.15f);
  Soup soup;
  for (int i = 0; i < 700; ++i) {
    if (!soup.shapes.empty()) soup.shapes += ",";
    char buf[512];
    if (i < 300 && i % 3 == 0) {
      std::snprintf(buf, sizeof buf, R"({"type": "sphere", "center": [%g, %g, %g], "radius": %g, "material": "m"})",
                    p(rng), p(rng), p(rng), r(rng));
    } else {
      const bool big = i < 300;
      const float x = big ? p(rng) : cluster(rng), y = big ? p(rng) : cluster(rng), z = big ? p(rng) : cluster(rng);
      auto& d = big ? e : small;
      const std::array<Vec3, 3> v = {Vec3{x, y, z}, Vec3{x + d(rng), y + d(rng), z + d(rng)},
                                     Vec3{x + d(rng), y + d(rng), z + d(rng)}};
      // %.9g: the vertices parse back to these floats exactly
      std::snprintf(
          buf, sizeof buf,
          R"({"type": "triangle", "vertices": [[%.9g, %.9g, %.9g], [%.9g, %.9g, %.9g], [%.9g, %.9g, %.9g]], "material": "m"})",
          v[0].x, v[0].y, v[0].z, v[1].x, v[1].y, v[1].z, v[2].x, v[2].y, v[2].z);
      soup.triangles.push_back(v);
    }
    soup.shapes += buf;
  }
  return soup;
}

// docs/determinism.md rule 4: every structure returns exactly the hit of brute force (which
// tests every primitive with the scalar test), ties included: the closest hit's primitive, t and
// barycentrics, and whether any hit lies within tmax.
void expect_every_structure_gives_the_brute_force_hits(const std::string& shapes, const std::vector<Ray>& rays,
                                                       const std::vector<float>& tmax, int min_hits) {
  RenderOverrides none;
  none.accel = AccelKind::None;
  const Scene brute = test::scene_from(one_shape_scene(shapes), none);
  const SceneView vb = brute.view();
  std::vector<Hit> closest;
  std::vector<bool> any;
  int hits = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    closest.push_back(trace_closest(vb, rays[i], kInfinity));
    any.push_back(trace_any(vb, rays[i], tmax[i]));
    hits += closest.back().prim != kNoHit;
  }
  EXPECT_GT(hits, min_hits);
  for (const AccelKind kind :
       {AccelKind::Bvh, AccelKind::Lbvh, AccelKind::Kdtree, AccelKind::KdtreeMedian, AccelKind::Grid}) {
    SCOPED_TRACE(enum_name(kind));
    RenderOverrides structure;
    structure.accel = kind;
    const Scene a = test::scene_from(one_shape_scene(shapes), structure);
    const SceneView va = a.view();
    for (size_t i = 0; i < rays.size(); ++i) {
      const Hit h = trace_closest(va, rays[i], kInfinity);
      ASSERT_EQ(h.prim, closest[i].prim) << "ray " << i;
      ASSERT_EQ(bits_of(h.t), bits_of(closest[i].t)) << "ray " << i;
      ASSERT_EQ(bits_of(h.b1), bits_of(closest[i].b1)) << "ray " << i;
      ASSERT_EQ(bits_of(h.b2), bits_of(closest[i].b2)) << "ray " << i;
      ASSERT_EQ(trace_any(va, rays[i], tmax[i]), any[i]) << "ray " << i;
    }
  }
}

}  // namespace

TEST(Accel, EveryStructureReturnsTheBruteForceHit) {
  std::mt19937 rng(21);
  const Soup soup = soup_with_a_cluster(rng);
  std::uniform_real_distribution<float> o(-8.0f, 8.0f), p(-5.0f, 5.0f), cluster(-0.7f, 0.7f);
  std::vector<Ray> rays;
  std::vector<float> tmax;
  for (int i = 0; i < 60000; ++i) {
    const Vec3 origin = {o(rng), o(rng), o(rng)};
    const Vec3 target = i % 2 == 0 ? Vec3{cluster(rng), cluster(rng), cluster(rng)} : Vec3{p(rng), p(rng), p(rng)};
    rays.push_back({origin, normalize(target - origin)});
    tmax.push_back(length(target - origin));
  }
  expect_every_structure_gives_the_brute_force_hits(soup.shapes, rays, tmax, 30000);
}

// Rays that leave a point on a triangle without an offset: the triangle they leave is at t
// within rounding of 0, which the watertight test's error bound on t rejects (kernel/geom/
// triangle.h); every structure's leaves must reject exactly what brute force does.
TEST(Accel, EveryStructureRejectsTheTriangleARayLeavesAsBruteForceDoes) {
  std::mt19937 rng(22);
  const Soup soup = soup_with_a_cluster(rng);
  std::uniform_real_distribution<float> b(0.0f, 1.0f), d(-1.0f, 1.0f);
  std::vector<Ray> rays;
  for (int i = 0; i < 40000; ++i) {
    const std::array<Vec3, 3>& v = soup.triangles[static_cast<size_t>(i) % soup.triangles.size()];
    float b1 = b(rng), b2 = b(rng);
    if (b1 + b2 > 1.0f) b1 = 1.0f - b1, b2 = 1.0f - b2;
    const Vec3 origin = v[0] + (v[1] - v[0]) * b1 + (v[2] - v[0]) * b2;
    rays.push_back({origin, normalize(Vec3{d(rng), d(rng), d(rng)})});
  }
  expect_every_structure_gives_the_brute_force_hits(soup.shapes, rays, std::vector<float>(rays.size(), kInfinity),
                                                    5000);
}

// Coincident triangles tie in t; the smaller primitive id wins whatever the structure.
TEST(Bvh, TieOnEqualTGoesToSmallerId) {
  std::string shapes;
  for (int i = 0; i < 12; ++i)
    shapes += std::string(i ? "," : "") +
              R"({"type": "triangle", "vertices": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], "material": "m"})";
  for (const char* accel : {"bvh", "none"}) {
    RenderOverrides ov;
    ov.accel = parse_enum<AccelKind>(accel, "accel");
    const Scene scene = test::scene_from(one_shape_scene(shapes), ov);
    const SceneView v = scene.view();
    for (float x : {-0.5f, 0.0f, 0.3f}) {
      const Hit h = trace_closest(v, {{x, 0.0f, 7.0f}, {0, 0, -1}}, kInfinity);
      EXPECT_EQ(h.prim, 0u) << accel;
      EXPECT_FLOAT_EQ(h.t, 7.0f) << accel;
    }
  }
}
