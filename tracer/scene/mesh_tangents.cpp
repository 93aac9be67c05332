#include "scene/mesh_tangents.h"

#include <map>
#include <tuple>

namespace tracer {

void compute_vertex_tangents(std::vector<MeshTriangle>& tris) {
  using Key = std::tuple<uint32_t, uint32_t, uint32_t, uint32_t, uint32_t>;  // position and uv bits
  const auto key = [](const MeshTriangle& t, int c) {
    return Key{bits_of(t.p[c].x), bits_of(t.p[c].y), bits_of(t.p[c].z), bits_of(t.uv[c][0]), bits_of(t.uv[c][1])};
  };
  std::map<Key, Vec3> sum;
  for (const MeshTriangle& t : tris) {
    if (!t.has_uvs || t.has_tangents) continue;
    const Vec3 e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0];
    const float du1 = t.uv[1][0] - t.uv[0][0], dv1 = t.uv[1][1] - t.uv[0][1];
    const float du2 = t.uv[2][0] - t.uv[0][0], dv2 = t.uv[2][1] - t.uv[0][1];
    const float det = du1 * dv2 - du2 * dv1;
    if (det == 0.0f) continue;
    // dp/du scaled by the uv determinant's sign: the area weight of the plain cross product.
    const Vec3 tangent = (e1 * dv2 - e2 * dv1) * (det > 0.0f ? 1.0f : -1.0f);
    for (int c = 0; c < 3; ++c) sum[key(t, c)] += tangent;
  }
  for (MeshTriangle& t : tris) {
    if (!t.has_uvs || t.has_tangents) continue;
    // dp/du x dp/dv = (e1 x e2) / det: n x dp/du turns to dp/dv where the normals face the
    // side of e1 x e2 and det > 0, or neither.
    const Vec3 e1 = t.p[1] - t.p[0], e2 = t.p[2] - t.p[0];
    const float det =
        (t.uv[1][0] - t.uv[0][0]) * (t.uv[2][1] - t.uv[0][1]) - (t.uv[2][0] - t.uv[0][0]) * (t.uv[1][1] - t.uv[0][1]);
    const Vec3 facing = t.has_normals ? t.n[0] + t.n[1] + t.n[2] : cross(e1, e2);
    t.bitangent_sign = (det < 0.0f) != (dot(facing, cross(e1, e2)) < 0.0f) ? -1.0f : 1.0f;
    t.has_tangents = true;
    for (int c = 0; c < 3; ++c) {
      const Vec3 s = sum[key(t, c)];
      const float len = length(s);
      t.tangent[c] = len > 0.0f ? s / len : Vec3{0.0f, 0.0f, 0.0f};
      if (!(len > 0.0f)) t.has_tangents = false;
    }
  }
}

}  // namespace tracer
