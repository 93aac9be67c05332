#include "scene/mesh_primitives.h"

#include "io/input_error.h"
#include "scene/mesh_tangents.h"

namespace tracer {

bool has_unit_normal(Vec3 e1, Vec3 e2) {
  const Vec3 n = normalize(cross(e1, e2));
  return is_finite(n) && length(n) > 0.5f;
}

void append_primitive(Scene& scene, const Primitive& p) {
  if (!is_finite(p.a) || !is_finite(p.b) || !is_finite(p.c) || !is_finite(p.radius))
    throw InputError(scene.file + ": a transformed shape has non-finite coordinates");
  scene.primitives.push_back(p);
}

namespace {

// A tangent is a direction in the surface: the part of the given one orthogonal to the
// vertex normal (Gram-Schmidt, in the file's frame, where both were given), placed as a
// vector (which keeps it orthogonal to the placed normal), normalised.
Vec3 placed_tangent(const Transform& xf, const MeshTriangle& t, int c) {
  Vec3 tangent = t.tangent[c];
  if (t.has_normals) {
    const Vec3 n = normalize(t.n[c]);
    tangent = tangent - n * dot(tangent, n);
  }
  const Vec3 v = xf.vector(tangent);
  const float len = length(v);
  return len > 0.0f ? v / len : Vec3{0.0f, 0.0f, 0.0f};
}

}  // namespace

size_t append_mesh_triangles(Scene& scene, std::vector<MeshTriangle> tris, const Transform& xf,
                             const std::vector<uint32_t>& materials, const std::function<void()>& zero_normal) {
  compute_vertex_tangents(tris);
  size_t kept = 0;
  for (size_t i = 0; i < tris.size(); ++i) {
    const MeshTriangle& t = tris[i];
    const Vec3 a = xf.point(t.p[0]), b = xf.point(t.p[1]), c = xf.point(t.p[2]);
    // A triangle without a geometric normal (surface.h) can never be shaded: left out.
    if (!has_unit_normal(b - a, c - a)) continue;
    ++kept;
    int32_t shading = -1;
    if (t.has_normals || t.has_uvs) {
      TriangleShading sh{};
      sh.bitangent_sign = 1.0f;
      if (t.has_normals) {
        for (int k = 0; k < 3; ++k)
          if (!(length(t.n[k]) > 0.0f)) zero_normal();
        sh.n0 = xf.normal(t.n[0]);
        sh.n1 = xf.normal(t.n[1]);
        sh.n2 = xf.normal(t.n[2]);
        sh.has_normals = 1;
      }
      if (t.has_uvs) {
        sh.u0 = t.uv[0][0], sh.v0 = t.uv[0][1], sh.u1 = t.uv[1][0], sh.v1 = t.uv[1][1];
        sh.u2 = t.uv[2][0], sh.v2 = t.uv[2][1];
        sh.has_uvs = 1;
      }
      if (t.has_tangents) {
        sh.t0 = placed_tangent(xf, t, 0);
        sh.t1 = placed_tangent(xf, t, 1);
        sh.t2 = placed_tangent(xf, t, 2);
        // A mirroring placement turns n x t against the placed bitangent: M(n x t) = det M (Mn x Mt).
        sh.bitangent_sign = xf.mirrors() ? -t.bitangent_sign : t.bitangent_sign;
        sh.has_tangents = 1;
      }
      shading = static_cast<int32_t>(scene.triangle_shading.size());
      scene.triangle_shading.push_back(sh);
    }
    append_primitive(scene, {ShapeKind::Triangle, materials[i], shading, 0.0f, a, b, c});
  }
  scene.report.degenerate_triangles += static_cast<uint32_t>(tris.size() - kept);
  return kept;
}

}  // namespace tracer
