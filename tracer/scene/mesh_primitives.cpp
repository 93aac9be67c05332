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
        sh.t0 = xf.vector(t.tangent[0]);
        sh.t1 = xf.vector(t.tangent[1]);
        sh.t2 = xf.vector(t.tangent[2]);
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
