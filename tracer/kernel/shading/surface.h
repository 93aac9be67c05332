// From a hit to the local surface: position, geometric and shading normals, uv (with textures).
#pragma once
#include "kernel/accel/trace.h"
#include "kernel/base/detmath.h"
#include "kernel/geom/hit_uv.h"
#include "kernel/material/bsdf.h"
#include "kernel/shading/sampling.h"

namespace tracer {

struct Surface {
  Vec3 p;
  Vec3 ng;  // unit geometric normal, outward as the shape (or its vertex normals) define it
  Vec3 ns;  // unit shading normal, on the same side as ng
  float u, v;          // texture coordinates: set only in a scene with textures, the one reader
  float bary1, bary2;  // triangles: the hit's barycentric weights of v1 and v2
  uint32_t material;
  uint32_t prim;
};

TRACER_HD Surface surface_at(const SceneView& scene, const Ray& ray, const Hit& hit) {
  const Primitive& prim = scene.primitives[hit.prim];
  Surface s;
  s.material = prim.material;
  s.prim = hit.prim;
  s.bary1 = hit.b1;
  s.bary2 = hit.b2;
  // The hit point is re-derived from the primitive (barycentrics, planar coordinates, a
  // projection onto the surface) rather than taken as o + t d: the origin offset of
  // ray_offset.h assumes a point accurate to a few ulps of its coordinates.
  switch (prim.kind) {
    case ShapeKind::Sphere:
      s.ng = sphere_hit_normal(prim, ray, hit.t);
      s.p = prim.a + s.ng * prim.radius;
      s.ns = s.ng;
      break;
    case ShapeKind::Plane:
      s.p = plane_hit_point(prim, ray, hit.t);
      s.ng = prim.b;
      s.ns = s.ng;
      break;
    case ShapeKind::Quad:
      s.p = prim.a + prim.b * hit.b1 + prim.c * hit.b2;
      s.ng = normalize(cross(prim.b, prim.c));
      s.ns = s.ng;
      break;
    case ShapeKind::Triangle: {
      s.ng = normalize(cross(prim.b - prim.a, prim.c - prim.a));
      s.ns = s.ng;
      const float b0 = 1.0f - hit.b1 - hit.b2;
      s.p = prim.a * b0 + prim.b * hit.b1 + prim.c * hit.b2;
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
      }
      break;
    }
  }
  // Only textures read (u, v): a scene without them skips the sphere's atan2 and asin.
  s.u = s.v = 0.0f;
  if (uses_feature(scene.features, kFeatureTextures)) hit_uv(scene, prim, ray, hit.t, hit.b1, hit.b2, s.u, s.v);
  return s;
}

// Unit tangent along increasing u at the surface point, orthogonal to the shading normal
// (Gram-Schmidt): from the triangle's uv derivatives, the quad's u edge, the sphere's
// longitude direction, the plane's frame; frame_around(ns) where those degenerate.
TRACER_HD Vec3 surface_tangent(const SceneView& scene, const Surface& s) {
  const Primitive& p = scene.primitives[s.prim];
  Vec3 t = {0.0f, 0.0f, 0.0f};
  switch (p.kind) {
    case ShapeKind::Quad: t = p.b; break;
    case ShapeKind::Plane: t = frame_around(p.b).t; break;
    case ShapeKind::Sphere: t = {-s.ng.z, 0.0f, s.ng.x}; break;  // along the longitude, the sphere map's u
    case ShapeKind::Triangle: {
      t = p.b - p.a;  // barycentric u when there are no uvs
      if (p.shading >= 0 && scene.triangle_shading[p.shading].has_tangents) {
        const TriangleShading& sh = scene.triangle_shading[p.shading];
        const float b1 = s.bary1, b2 = s.bary2;
        t = sh.t0 * (1.0f - b1 - b2) + sh.t1 * b1 + sh.t2 * b2;
      } else if (p.shading >= 0 && scene.triangle_shading[p.shading].has_uvs) {
        const TriangleShading& sh = scene.triangle_shading[p.shading];
        const float du1 = sh.u1 - sh.u0, dv1 = sh.v1 - sh.v0, du2 = sh.u2 - sh.u0, dv2 = sh.v2 - sh.v0;
        const float det = du1 * dv2 - du2 * dv1;
        if (det != 0.0f) t = ((p.b - p.a) * dv2 - (p.c - p.a) * dv1) / det;
      }
      break;
    }
  }
  t = t - s.ns * dot(t, s.ns);
  const float len = length(t);
  return len > 0.0f ? t / len : frame_around(s.ns).t;
}

// The sign that makes bitangent_sign * (ns x t) the surface's bitangent: a triangle's own
// (glTF's TANGENT w, turned by a mirroring placement), else 1.
TRACER_HD float bitangent_sign(const SceneView& scene, const Surface& s) {
  const Primitive& p = scene.primitives[s.prim];
  if (p.kind != ShapeKind::Triangle || p.shading < 0 || !scene.triangle_shading[p.shading].has_tangents) return 1.0f;
  return scene.triangle_shading[p.shading].bitangent_sign;
}

// The material at a surface point with its textured colours looked up at (u, v).
TRACER_HD Material material_colours_at(const SceneView& scene, const Surface& s) {
  Material m = scene.materials[s.material];
  if (!uses_feature(scene.features, kFeatureTextures)) return m;
  Vec3* colour[kColourSlots] = {&m.albedo, &m.ambient, &m.specular, &m.tint, &m.radiance};
  for (uint32_t k = 0; k < kColourSlots; ++k)
    if (m.texture[k] != kNoTexture) *colour[k] = sample_texture(scene.textures, scene.texels, m.texture[k], s.u, s.v);
  if (m.factor_map != kNoTexture) {
    const Vec3 f = sample_texture(scene.textures, scene.texels, m.factor_map, s.u, s.v);
    apply_factor_map(m, f);  // the kind's (kernel/material/bsdf.h)
  }
  return m;
}

// The material at a surface point: its textured colours, and a normal or bump map bends s.ns.
// Unit map values that leave the normal unchanged (a normal map of (0.5, 0.5, 1), a flat
// height field) leave it unchanged bit for bit.
TRACER_HD Material material_at(const SceneView& scene, Surface& s) {
  const Material m = material_colours_at(scene, s);
  if (!uses_feature(scene.features, kFeatureTextures)) return m;
  if (m.normal_map == kNoTexture && m.bump_map == kNoTexture) return m;
  const Vec3 t = surface_tangent(scene, s), b = cross(s.ns, t) * bitangent_sign(scene, s);
  Vec3 local = {0.0f, 0.0f, 1.0f};
  if (m.normal_map != kNoTexture) {
    local = sample_texture(scene.textures, scene.texels, m.normal_map, s.u, s.v) * 2.0f - Vec3{1.0f, 1.0f, 1.0f};
  } else {
    // Heights by central differences one texel apart; a height step of 1 across a texel
    // tilts the normal by 45 degrees.
    const Texture& h = scene.textures[m.bump_map];
    const float du = 1.0f / static_cast<float>(h.width), dv = 1.0f / static_cast<float>(h.height);
    const float hu = sample_texture(scene.textures, scene.texels, m.bump_map, s.u + du, s.v).x -
                     sample_texture(scene.textures, scene.texels, m.bump_map, s.u - du, s.v).x;
    const float hv = sample_texture(scene.textures, scene.texels, m.bump_map, s.u, s.v + dv).x -
                     sample_texture(scene.textures, scene.texels, m.bump_map, s.u, s.v - dv).x;
    local = {-0.5f * hu, -0.5f * hv, 1.0f};
  }
  if (local.x == 0.0f && local.y == 0.0f && local.z > 0.0f) return m;
  const Vec3 n = glm::mat3(t, b, s.ns) * local;  // tangent space to world
  const float len = length(n);
  if (len > 0.0f && dot(n, s.ng) * dot(s.ns, s.ng) > 0.0f) s.ns = n / len;  // stays on the shading side
  return m;
}

}  // namespace tracer
