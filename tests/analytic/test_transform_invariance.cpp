// Invariances whose answer does not come from the renderer (docs/gltf.md, "Transforms"): a mesh
// with vertex normals, tangents and a normal map placed by an affine transform renders as its
// twin whose vertices the test transformed in double precision; a glTF node hierarchy renders
// as its transforms baked into copies of the mesh; a whole scene moved rigidly renders the same
// image, and mirrored, the mirror image.
//
// Tolerance: the two files differ only in where float rounding happens (the tracer's float
// product of the node matrices and each vertex against the test's double one, rounded once
// when written), a few ulps of every coordinate, normal and tangent. The images are smooth
// functions of those except where a ray passes within rounding distance of a discontinuity
// (the silhouette, a shadow's edge), so a pixel may differ by at most 1e-4 of its value
// (a hundred times the error those ulps propagate to), and at most 1 % of the pixels (the
// discontinuities') by more. The mutants of ci/mutants.txt (a normal by the inverse instead of
// the inverse transpose, a mirrored bitangent, node matrices in the wrong order) move the
// shading of most pixels by percent.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "gltf_builder.h"
#include "image/image_io.h"
#include "render/render_cpu.h"
#include "scene/scene_loader.h"
#include "scene/transform.h"
#include "test_util.h"

namespace tracer {
namespace {

using D3 = std::array<double, 3>;

D3 cross3(const D3& a, const D3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot3(const D3& a, const D3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
D3 unit(const D3& a) {
  const double l = std::sqrt(dot3(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}

// p' = m p + t, in double; every entry a float, as the file stores it.
struct Affine {
  double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  D3 t = {0, 0, 0};

  D3 point(const D3& p) const { return add(vector(p), t); }
  D3 vector(const D3& v) const {
    return {dot3({m[0][0], m[0][1], m[0][2]}, v), dot3({m[1][0], m[1][1], m[1][2]}, v),
            dot3({m[2][0], m[2][1], m[2][2]}, v)};
  }
  D3 column(int c) const { return {m[0][c], m[1][c], m[2][c]}; }
  double det() const { return dot3(column(0), cross3(column(1), column(2))); }
  // By the inverse transpose: (M^-T n)_k = sum_i n_i (row i of M^-1)_k, row i of M^-1 being
  // the cross product of the other two columns over det; the |det| keeps its side.
  D3 normal(const D3& n) const {
    const D3 r0 = cross3(column(1), column(2)), r1 = cross3(column(2), column(0)), r2 = cross3(column(0), column(1));
    const double s = det() < 0 ? -1.0 : 1.0;
    return unit({s * (r0[0] * n[0] + r1[0] * n[1] + r2[0] * n[2]), s * (r0[1] * n[0] + r1[1] * n[1] + r2[1] * n[2]),
                 s * (r0[2] * n[0] + r1[2] * n[1] + r2[2] * n[2])});
  }
  static D3 add(const D3& a, const D3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

  // this after `first`
  Affine after(const Affine& first) const {
    Affine r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        r.m[i][j] = m[i][0] * first.m[0][j] + m[i][1] * first.m[1][j] + m[i][2] * first.m[2][j];
    r.t = point(first.t);
    return r;
  }
  Affine rounded() const {
    Affine r = *this;
    for (auto& row : r.m)
      for (double& v : row) v = static_cast<float>(v);
    for (double& v : r.t) v = static_cast<float>(v);
    return r;
  }
  // glTF's column-major matrix
  nlohmann::json gltf() const {
    return {m[0][0], m[1][0], m[2][0], 0, m[0][1], m[1][1], m[2][1], 0,
            m[0][2], m[1][2], m[2][2], 0, t[0],    t[1],    t[2],    1};
  }
};

Affine rotation(D3 axis, double degrees) {
  const D3 k = unit(axis);
  const double a = degrees * M_PI / 180.0, c = std::cos(a), s = std::sin(a), o = 1 - c;
  Affine r;
  const double m[3][3] = {{c + k[0] * k[0] * o, k[0] * k[1] * o - k[2] * s, k[0] * k[2] * o + k[1] * s},
                          {k[1] * k[0] * o + k[2] * s, c + k[1] * k[1] * o, k[1] * k[2] * o - k[0] * s},
                          {k[2] * k[0] * o - k[1] * s, k[2] * k[1] * o + k[0] * s, c + k[2] * k[2] * o}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r.m[i][j] = m[i][j];
  return r;
}
Affine linear(std::array<double, 9> rows, D3 t = {0, 0, 0}) {
  Affine r;
  for (int i = 0; i < 9; ++i) r.m[i / 3][i % 3] = rows[i];
  r.t = t;
  return r;
}
Affine scaling(double x, double y, double z) { return linear({x, 0, 0, 0, y, 0, 0, 0, z}); }

// Per vertex: position, unit normal, unit tangent along +u (skewed toward the normal, as a
// file may give it) with w = +1 or -1, uv.
struct Mesh {
  std::vector<D3> p, n, t;
  std::vector<double> w;
  std::vector<std::array<double, 2>> uv;
  std::vector<uint32_t> indices;
};

// A saddle z = 0.3 (x^2 - y^2) + 0.15 x y over [-1, 1]^2, k x k quads, its normals and tangents
// from the height's derivatives (exact, not from the triangles); uvs mirrored in v where
// mirror_v, which turns the bitangent (w = -1).
Mesh saddle(int k, bool mirror_v) {
  Mesh mesh;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) {
      const double x = -1 + 2.0 * i / k, y = -1 + 2.0 * j / k;
      const double hx = 0.6 * x + 0.15 * y, hy = -0.6 * y + 0.15 * x;
      mesh.p.push_back({x, y, 0.3 * (x * x - y * y) + 0.15 * x * y});
      mesh.n.push_back(unit({-hx, -hy, 1}));
      const D3 along = unit({1, 0, hx}), n = mesh.n.back();
      mesh.t.push_back(unit({along[0] + 0.3 * n[0], along[1] + 0.3 * n[1], along[2] + 0.3 * n[2]}));
      mesh.w.push_back(mirror_v ? -1.0 : 1.0);
      mesh.uv.push_back({(x + 1) * 0.75, mirror_v ? (1 - y) * 0.75 : (y + 1) * 0.75});
    }
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const uint32_t a = j * (k + 1) + i, b = a + 1, c = a + k + 1, d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, b, d, a, d, c});
    }
  return mesh;
}

// The mesh with `a` applied to its vertices in double: positions as points, normals by the
// inverse transpose, tangents (their part orthogonal to the normal) as vectors; a mirroring
// `a` turns the bitangent's sign.
Mesh baked(const Mesh& mesh, const Affine& a) {
  Mesh out = mesh;
  for (size_t v = 0; v < mesh.p.size(); ++v) {
    out.p[v] = a.point(mesh.p[v]);
    out.n[v] = a.normal(mesh.n[v]);
    const D3 &t = mesh.t[v], &n = mesh.n[v];
    const double along = dot3(t, n);
    out.t[v] = unit(a.vector({t[0] - along * n[0], t[1] - along * n[1], t[2] - along * n[2]}));
    out.w[v] = a.det() < 0 ? -mesh.w[v] : mesh.w[v];
  }
  return out;
}

// The tangents the reader computes for a mesh without them (mesh_tangents.h), in double:
// each triangle's dp/du times the sign of its uv determinant summed at its vertices and
// normalised; the bitangent's sign -1 where the uvs are mirrored against the normals. The
// uvs are the reader's (v = 1 - glTF's v).
Mesh with_computed_tangents(Mesh mesh) {
  std::vector<D3> sum(mesh.p.size(), D3{0, 0, 0});
  for (size_t k = 0; k < mesh.indices.size(); k += 3) {
    const uint32_t i0 = mesh.indices[k], i1 = mesh.indices[k + 1], i2 = mesh.indices[k + 2];
    const D3 e1 = {mesh.p[i1][0] - mesh.p[i0][0], mesh.p[i1][1] - mesh.p[i0][1], mesh.p[i1][2] - mesh.p[i0][2]};
    const D3 e2 = {mesh.p[i2][0] - mesh.p[i0][0], mesh.p[i2][1] - mesh.p[i0][1], mesh.p[i2][2] - mesh.p[i0][2]};
    const double du1 = mesh.uv[i1][0] - mesh.uv[i0][0], dv1 = mesh.uv[i0][1] - mesh.uv[i1][1];
    const double du2 = mesh.uv[i2][0] - mesh.uv[i0][0], dv2 = mesh.uv[i0][1] - mesh.uv[i2][1];
    const double det = du1 * dv2 - du2 * dv1, s = det > 0 ? 1 : -1;
    const D3 facing = Affine::add(Affine::add(mesh.n[i0], mesh.n[i1]), mesh.n[i2]);
    const double w = (det < 0) != (dot3(facing, cross3(e1, e2)) < 0) ? -1 : 1;
    for (const uint32_t i : {i0, i1, i2}) {
      for (int c = 0; c < 3; ++c) sum[i][c] += (e1[c] * dv2 - e2[c] * dv1) * s;
      mesh.w[i] = w;
    }
  }
  for (size_t v = 0; v < mesh.p.size(); ++v) mesh.t[v] = unit(sum[v]);
  return mesh;
}

// One node of the scene: a mesh (or none) under a chain of matrices, outermost first.
struct Instance {
  int mesh;
  std::vector<Affine> chain;
};

// A scene of meshes, a camera looking at `target` from `eye`, and a point light; everything
// under the root matrix `root`. The meshes share a normal-mapped metal_rough material.
struct SceneSpec {
  std::vector<Mesh> meshes;
  std::vector<Instance> instances;
  D3 eye, target, light;
  Affine root;
  bool tangents = true;  // false: no TANGENT, the reader computes them from the uvs
};

nlohmann::json scene_document(const SceneSpec& spec) {
  test::GltfDoc g;
  g.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  g.doc["images"] = {{{"uri", "bumps.png"}}};
  g.doc["textures"] = {{{"source", 0}}};
  g.doc["materials"] = {{{"pbrMetallicRoughness",
                          {{"baseColorFactor", {0.8, 0.6, 0.4, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0.45}}},
                         {"normalTexture", {{"index", 0}}},
                         {"doubleSided", true}}};
  for (const Mesh& m : spec.meshes) {
    std::vector<float> p, n, t, uv;
    for (size_t v = 0; v < m.p.size(); ++v) {
      for (int c = 0; c < 3; ++c)
        p.push_back(float(m.p[v][c])), n.push_back(float(m.n[v][c])), t.push_back(float(m.t[v][c]));
      t.push_back(float(m.w[v]));
      uv.push_back(float(m.uv[v][0])), uv.push_back(float(m.uv[v][1]));
    }
    nlohmann::json attributes = {{"POSITION", g.floats(p, "VEC3", 3, true)},
                                 {"NORMAL", g.floats(n, "VEC3", 3)},
                                 {"TEXCOORD_0", g.floats(uv, "VEC2", 2)}};
    if (spec.tangents) attributes["TANGENT"] = g.floats(t, "VEC4", 4);
    g.push("meshes",
           {{"primitives", {{{"attributes", attributes}, {"indices", g.indices(m.indices)}, {"material", 0}}}}});
  }
  std::vector<int> children;
  for (const Instance& in : spec.instances) {
    int child = -1;
    for (size_t k = in.chain.size(); k-- > 0;) {
      nlohmann::json node = {{"matrix", in.chain[k].gltf()}};
      if (child < 0)
        node["mesh"] = in.mesh;
      else
        node["children"] = {child};
      child = g.push("nodes", node);
    }
    if (child < 0) child = g.push("nodes", {{"mesh", in.mesh}});
    children.push_back(child);
  }
  // The camera's node matrix: columns right, up, back (glTF cameras look down -z), the eye.
  const D3 ahead = unit({spec.target[0] - spec.eye[0], spec.target[1] - spec.eye[1], spec.target[2] - spec.eye[2]});
  const D3 right = unit(cross3(ahead, {0, 1, 0})), up = cross3(right, ahead);
  Affine view = linear({right[0], up[0], -ahead[0], right[1], up[1], -ahead[1], right[2], up[2], -ahead[2]}, spec.eye);
  g.push("cameras", {{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"aspectRatio", 1.0}, {"znear", 0.01}}}});
  children.push_back(g.push("nodes", {{"camera", 0}, {"matrix", view.rounded().gltf()}}));
  g.doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "point"}, {"intensity", 40.0}}};
  children.push_back(g.push("nodes", {{"translation", {spec.light[0], spec.light[1], spec.light[2]}},
                                      {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}));
  const int root = g.push("nodes", {{"matrix", spec.root.gltf()}, {"children", children}});
  g.doc["scenes"][0]["nodes"] = {root};
  return g.finish();
}

// A normal map of tilts that vary across it, none symmetric in u or v.
void write_bumps(const std::filesystem::path& dir) {
  const Image img = test::image_from(8, 8, [](uint32_t x, uint32_t y) {
    const double tx = 0.45 * std::sin(0.9 * x + 0.3), ty = 0.35 * std::cos(1.3 * y + 0.2 * x);
    const D3 n = unit({tx, ty, 1});
    return Vec3{float(n[0] * 0.5 + 0.5), float(n[1] * 0.5 + 0.5), float(n[2] * 0.5 + 0.5)};
  });
  write_image(img, (dir / "bumps.png").string());
}

Image render(const std::filesystem::path& dir, const std::string& name, const SceneSpec& spec,
             IntegratorKind integrator) {
  const std::string file = test::write_gltf(dir / name, scene_document(spec));
  RenderOverrides ov;
  ov.width = 48;
  ov.height = 48;
  ov.spp = 1;
  ov.sampler = SamplerKind::Center;
  ov.integrator = integrator;
  RenderStats stats;
  return render_cpu(load_scene(file, ov), 1, stats);
}

// Pixels whose largest channel difference exceeds 1e-4 of the larger value (and 1e-6).
double fraction_apart(const Image& a, const Image& b) {
  size_t apart = 0;
  for (size_t i = 0; i + 2 < a.rgb.size(); i += 3) {
    double d = 0, v = 0;
    for (int c = 0; c < 3; ++c)
      d = std::max(d, std::abs(double(a.rgb[i + c]) - b.rgb[i + c])),
      v = std::max({v, std::abs(double(a.rgb[i + c])), std::abs(double(b.rgb[i + c]))});
    if (d > std::max(1e-4 * v, 1e-6)) ++apart;
  }
  return double(apart) / double(a.rgb.size() / 3);
}

Image flipped(const Image& a) {
  Image out = a;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) out.rgb[(y * a.width + x) * 3 + c] = a.rgb[(y * a.width + (a.width - 1 - x)) * 3 + c];
  return out;
}

constexpr double kMostPixels = 0.01;  // the share allowed past 1e-4: rays at a discontinuity

// A camera and a light around the baked meshes' bounding sphere.
SceneSpec framed(std::vector<Mesh> meshes, std::vector<Instance> instances, const std::vector<Mesh>& world) {
  D3 lo = {1e30, 1e30, 1e30}, hi = {-1e30, -1e30, -1e30};
  for (const Mesh& m : world)
    for (const D3& p : m.p)
      for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], p[c]), hi[c] = std::max(hi[c], p[c]);
  const D3 centre = {(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
  const double r =
      std::sqrt(dot3({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}, {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]})) / 2;
  SceneSpec s;
  s.meshes = std::move(meshes);
  s.instances = std::move(instances);
  s.target = centre;
  s.eye = {centre[0] + 0.9 * r, centre[1] + 1.1 * r, centre[2] + 2.6 * r};
  s.light = {centre[0] - 1.5 * r, centre[1] + 2.5 * r, centre[2] + 2.0 * r};
  return s;
}

// The placements: the rotation the bug showed, non-uniform scales, shears, mirrors, and
// random ones (rotation x scale of either sign x shear).
std::vector<std::pair<std::string, Affine>> placements() {
  std::vector<std::pair<std::string, Affine>> out = {
      {"rotate z 40", rotation({0, 0, 1}, 40)},
      {"scale 2 0.5 1.3, rotate", rotation({1, 2, 3}, 70).after(scaling(2, 0.5, 1.3))},
      {"shear", rotation({-1, 1, 0.5}, 35).after(linear({1, 0.6, 0, 0, 1, 0, -0.4, 0, 1}, {0.3, -0.2, 0.1}))},
      {"mirror x", scaling(-1, 1, 1)},
      {"mirror, scale, rotate", rotation({0, 1, 1}, 30).after(scaling(1.5, -0.7, 1))},
  };
  test::InputStream rng{55};
  for (int k = 0; k < 4; ++k) {
    const auto u = [&](double lo, double hi) { return lo + (hi - lo) * rng.next(); };
    const Affine shear = linear({1, u(-0.5, 0.5), u(-0.5, 0.5), 0, 1, u(-0.5, 0.5), 0, 0, 1});
    const Affine scale = scaling(u(0.4, 2.5) * (rng.next() < 0.5 ? -1 : 1), u(0.4, 2.5), u(0.4, 2.5));
    const Affine rot = rotation({u(-1, 1), u(-1, 1), u(-1, 1)}, u(-180, 180));
    Affine a = rot.after(scale).after(shear);
    a.t = {u(-3, 3), u(-3, 3), u(-3, 3)};
    out.push_back({"random " + std::to_string(k), a});
  }
  for (auto& [name, a] : out) a = a.rounded();
  return out;
}

TEST(TransformInvariance, NormalsStayPerpendicularToTransformedSurfaces) {
  // For any plane through the origin with normal n, Transform::normal(n) is perpendicular to
  // the transformed plane (the images of two vectors in it) and on the side of the image of n.
  for (const auto& [name, a] : placements()) {
    Transform xf;
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) xf.m[c][r] = float(a.m[r][c]);
    test::InputStream rng{7};
    for (int k = 0; k < 50; ++k) {
      const D3 n = unit({rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5});
      const D3 e1 = unit(cross3(n, {0.3, 0.5, 0.8})), e2 = cross3(n, e1);
      const Vec3 got = xf.normal({float(n[0]), float(n[1]), float(n[2])});
      const D3 g = {got.x, got.y, got.z};
      EXPECT_NEAR(dot3(g, unit(a.vector(e1))), 0.0, 1e-5) << name;
      EXPECT_NEAR(dot3(g, unit(a.vector(e2))), 0.0, 1e-5) << name;
      EXPECT_GT(dot3(g, a.vector(n)), 0.0) << name;
    }
  }
}

TEST(TransformInvariance, APlacedMeshShadesAsItsTwinTransformedInDouble) {
  const auto dir = test::temp_dir("twin");
  write_bumps(dir);
  for (const bool mirror_v : {false, true})
    for (const bool tangents : {true, false}) {
      const Mesh mesh = saddle(12, mirror_v);
      for (const auto& [name, a] : placements()) {
        const Mesh twin = baked(tangents ? mesh : with_computed_tangents(mesh), a);
        SceneSpec placed = framed({mesh}, {{0, {a}}}, {twin});
        placed.tangents = tangents;
        SceneSpec baked_spec = placed;
        baked_spec.tangents = true;
        baked_spec.meshes = {twin};
        baked_spec.instances = {{0, {}}};
        for (const IntegratorKind integrator : {IntegratorKind::Normals, IntegratorKind::Whitted}) {
          const Image x = render(dir, "placed.gltf", placed, integrator),
                      y = render(dir, "twin.gltf", baked_spec, integrator);
          EXPECT_LE(fraction_apart(x, y), kMostPixels)
              << name << (mirror_v ? ", mirrored uvs" : "") << (tangents ? "" : ", tangents from the uvs")
              << ", integrator " << int(integrator);
        }
      }
    }
  std::filesystem::remove_all(dir);
}

TEST(TransformInvariance, ANodeHierarchyRendersAsItsTransformsBakedIntoCopies) {
  // A root of translation, rotation and scale, a child sheared under it holding the mesh, and
  // a second node using the same mesh: as two copies of the mesh, each baked in double.
  const auto dir = test::temp_dir("hierarchy");
  write_bumps(dir);
  const Mesh mesh = saddle(10, false);
  const Affine outer = rotation({0.2, 1, 0.3}, 50).after(scaling(1.2, 0.8, 1.0)).rounded();
  Affine outer_moved = outer;
  outer_moved.t = {0.3, -0.2, 0.5};
  const Affine inner =
      linear({1, 0.3, 0, 0, 1, 0, 0.2, 0, 0.9}, {1.5, 0, -0.5}).after(rotation({1, 0, 0}, -60)).rounded();
  const Affine second =
      linear({0.7, 0, 0, 0, 0.7, 0, 0, 0, 0.7}, {-1.8, 0.4, 0.2}).after(rotation({0, 1, 0}, 120)).rounded();
  const std::vector<Mesh> world = {baked(mesh, outer_moved.after(inner)), baked(mesh, second)};
  const SceneSpec tree = framed({mesh}, {{0, {outer_moved, inner}}, {0, {second}}}, world);
  SceneSpec copies = tree;
  copies.meshes = world;
  copies.instances = {{0, {}}, {1, {}}};
  for (const IntegratorKind integrator : {IntegratorKind::Normals, IntegratorKind::Whitted}) {
    const Image x = render(dir, "tree.gltf", tree, integrator), y = render(dir, "copies.gltf", copies, integrator);
    EXPECT_LE(fraction_apart(x, y), kMostPixels) << "integrator " << int(integrator);
  }
  std::filesystem::remove_all(dir);
}

TEST(TransformInvariance, ASceneMovedRigidlyRendersTheSameAndMirroredTheMirrorImage) {
  // Camera, light and meshes under one root: a rotation and translation leave the image as it
  // was; a reflection (a Householder matrix, then a rotation) flips it left to right, since
  // the camera's right is ahead x up whatever the placement.
  const auto dir = test::temp_dir("rigid");
  write_bumps(dir);
  const Mesh mesh = saddle(12, false);
  const Affine a = placements()[2].second;
  const SceneSpec scene = framed({baked(mesh, a)}, {{0, {}}}, {baked(mesh, a)});
  SceneSpec moved = scene, mirrored = scene;
  moved.root = rotation({0.3, 1, 0.2}, 57).rounded();
  moved.root.t = {5, -3, 2};
  const D3 h = unit({1, 0.2, 0.1});
  const Affine householder =
      linear({1 - 2 * h[0] * h[0], -2 * h[0] * h[1], -2 * h[0] * h[2], -2 * h[1] * h[0], 1 - 2 * h[1] * h[1],
              -2 * h[1] * h[2], -2 * h[2] * h[0], -2 * h[2] * h[1], 1 - 2 * h[2] * h[2]});
  mirrored.root = rotation({0, 0, 1}, 20).after(householder).rounded();
  mirrored.root.t = {-1, 2, 0.5};
  for (const IntegratorKind integrator : {IntegratorKind::Whitted, IntegratorKind::Albedo}) {
    const Image x = render(dir, "scene.gltf", scene, integrator);
    EXPECT_LE(fraction_apart(x, render(dir, "moved.gltf", moved, integrator)), kMostPixels) << int(integrator);
    EXPECT_LE(fraction_apart(flipped(x), render(dir, "mirrored.gltf", mirrored, integrator)), kMostPixels)
        << int(integrator);
  }
  std::filesystem::remove_all(dir);
}

TEST(TransformInvariance, AJsonMeshRotatedShadesAsItsRotatedTwin) {
  // The scene format's own transform: a quad with tilted vertex normals under "rotate z 40"
  // against the same quad with positions and normals rotated in double.
  const Affine r = rotation({0, 0, 1}, 40);
  const std::vector<D3> p = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  const std::vector<D3> n = {unit({0.5, 0.1, 1}), unit({-0.3, 0.4, 1}), unit({0.2, -0.5, 1}), unit({-0.4, -0.2, 1})};
  const auto list = [](const std::vector<D3>& v) {
    nlohmann::json out = nlohmann::json::array();
    for (const D3& x : v) out.push_back({float(x[0]), float(x[1]), float(x[2])});
    return out;
  };
  std::vector<D3> rp, rn;
  for (size_t k = 0; k < p.size(); ++k) rp.push_back(r.point(p[k])), rn.push_back(r.normal(n[k]));
  const auto scene = [&](const std::vector<D3>& ps, const std::vector<D3>& ns, bool transformed) {
    nlohmann::json doc = nlohmann::json::parse(R"({"format": "tracer-scene/1",
      "camera": {"from": [0.2, -0.3, 2.2], "to": [0, 0, 0], "vfov": 60}, "film": {"width": 48, "height": 48},
      "render": {"integrator": "whitted", "sampler": "center", "max_depth": 1},
      "materials": {"m": {"type": "phong", "diffuse": [0.6, 0.6, 0.6], "specular": [0.4, 0.4, 0.4], "shininess": 30}},
      "lights": [{"type": "point", "position": [0.8, 0.5, 1.5], "intensity": [3, 3, 3]}]})");
    nlohmann::json mesh = {{"type", "mesh"},
                           {"material", "m"},
                           {"positions", list(ps)},
                           {"normals", list(ns)},
                           {"indices", {{0, 1, 2}, {0, 2, 3}}}};
    if (transformed) mesh["transform"] = {{{"rotate", {{"axis", {0, 0, 1}}, {"degrees", 40}}}}};
    doc["shapes"] = nlohmann::json::array({mesh});  // {mesh} alone is a copy under clang
    RenderStats stats;
    return render_cpu(test::scene_from(doc.dump()), 1, stats);
  };
  EXPECT_LE(fraction_apart(scene(p, n, true), scene(rp, rn, false)), kMostPixels);
}

}  // namespace
}  // namespace tracer
