// From a hit to the local surface: position, geometric and shading normals, uv.
#pragma once
#include "detmath.h"
#include "sampling.h"
#include "trace.h"

namespace tracer {

struct Surface {
  Vec3 p;
  Vec3 ng;  // unit geometric normal, outward as the shape (or its vertex normals) define it
  Vec3 ns;  // unit shading normal, on the same side as ng
  float u, v;
  uint32_t material;
};

TRACER_HD Surface surface_at(const SceneView& scene, const Ray& ray, const Hit& hit) {
  const Primitive& prim = scene.primitives[hit.prim];
  Surface s;
  s.material = prim.material;
  // The hit point is re-derived from the primitive (barycentrics, planar coordinates, a
  // projection onto the surface) rather than taken as o + t d: the origin offset of
  // ray_offset.h assumes a point accurate to a few ulps of its coordinates.
  switch (prim.kind) {
    case ShapeKind::Sphere: {
      const Vec3 rel = ray_at(ray, hit.t) - prim.a;
      s.ng = normalize(rel);
      s.p = prim.a + s.ng * prim.radius;
      // u = 0.5 + atan2(z, x) / 2 pi, v = 0.5 - asin(y) / pi (SCENE_FORMAT's sphere map)
      s.u = 0.5f + det_atan2(s.ng.z, s.ng.x) / (2.0f * kPi);
      s.v = 0.5f - det_asin(clamp_of(s.ng.y, -1.0f, 1.0f)) / kPi;
      s.ns = s.ng;
      break;
    }
    case ShapeKind::Plane: {
      const Vec3 q = ray_at(ray, hit.t);
      s.p = q - prim.b * dot(q - prim.a, prim.b);
      s.ng = prim.b;
      s.ns = s.ng;
      // planar coordinates in the frame of sampling.h's frame_around(normal)
      const Frame f = frame_around(prim.b);
      s.u = dot(s.p - prim.a, f.t);
      s.v = dot(s.p - prim.a, f.b);
      break;
    }
    case ShapeKind::Quad:
      s.p = prim.a + prim.b * hit.b1 + prim.c * hit.b2;
      s.ng = normalize(cross(prim.b, prim.c));
      s.ns = s.ng;
      s.u = hit.b1;
      s.v = hit.b2;
      break;
    case ShapeKind::Triangle: {
      s.ng = normalize(cross(prim.b - prim.a, prim.c - prim.a));
      s.ns = s.ng;
      const float b0 = 1.0f - hit.b1 - hit.b2;
      s.p = prim.a * b0 + prim.b * hit.b1 + prim.c * hit.b2;
      s.u = hit.b1;
      s.v = hit.b2;
      if (prim.shading >= 0) {
        const TriangleShading& sh = scene.triangle_shading[prim.shading];
        if (sh.has_normals) {
          const Vec3 n = sh.n0 * b0 + sh.n1 * hit.b1 + sh.n2 * hit.b2;
          const float len = length(n);
          if (len > 0.0f) {
            s.ns = n / len;
            // vertex normals state which side is outside: turn ng to agree with them
            if (dot(s.ns, s.ng) < 0.0f) s.ng = -s.ng;
          }
        }
        if (sh.has_uvs) {
          s.u = sh.u0 * b0 + sh.u1 * hit.b1 + sh.u2 * hit.b2;
          s.v = sh.v0 * b0 + sh.v1 * hit.b1 + sh.v2 * hit.b2;
        }
      }
      break;
    }
  }
  return s;
}

// The material at a surface point: its textured colours looked up at (u, v).
TRACER_HD Material material_at(const SceneView& scene, const Surface& s) {
  Material m = scene.materials[s.material];
  if (!(scene.features & kFeatureTextures)) return m;
  Vec3* colour[kColourSlots] = {&m.albedo, &m.ambient, &m.specular, &m.tint, &m.radiance};
  for (uint32_t k = 0; k < kColourSlots; ++k)
    if (m.texture[k] != kNoTexture) *colour[k] = sample_texture(scene.textures, scene.texels, m.texture[k], s.u, s.v);
  return m;
}

}  // namespace tracer
