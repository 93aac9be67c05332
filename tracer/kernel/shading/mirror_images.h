// Next-event estimation through a flat mirror (render.mirror_images): light that reaches a
// point x off one planar mirror comes from the light's mirror image, so it can be sampled like
// the light itself. Reflect x across the mirror's plane to x', sample the light from x' (a
// reflection is an isometry: the image subtends from x the solid angle the light subtends from
// x'), and fold the sampled direction back across the plane. The path x -> mirror -> light is
// also found by BSDF sampling at x (a specular bounce, then the light), so the two strategies
// are weighted against each other by the power heuristic (Veach 1997); with one image chosen
// per vertex its density is the light's selection probability over the mirror count times
// 1 / the solid angle from x'. A planar mirror is a plane, quad or flat triangle (no shading
// normals, normal or bump map) of a perfect mirror (its kind's is_perfect_mirror: metal of roughness
// 0 or a smooth conductor), with no texture on its colour. Point lights and the sky have no image: only shapes are
// sampled.
#pragma once
#include "kernel/accel/primitive_hit.h"
#include "kernel/base/float_to_int.h"
#include "kernel/light/light.h"
#include "kernel/material/bsdf.h"

namespace tracer {

TRACER_HD bool is_planar_mirror(const SceneView& scene, const Primitive& p) {
  if (p.kind == ShapeKind::Sphere) return false;
  if (p.kind == ShapeKind::Triangle && p.shading >= 0 && scene.triangle_shading[p.shading].has_normals != 0u)
    return false;
  const Material& m = scene.materials[p.material];
  return is_perfect_mirror(m) && m.texture[kSlotAlbedo] == kNoTexture && m.normal_map == kNoTexture &&
         m.bump_map == kNoTexture;
}

// The unit normal of a planar mirror's plane (its geometric normal).
TRACER_HD Vec3 mirror_normal(const Primitive& p) {
  switch (p.kind) {
    case ShapeKind::Plane: return p.b;
    case ShapeKind::Quad: return normalize(cross(p.b, p.c));
    default: return normalize(cross(p.b - p.a, p.c - p.a));
  }
}

// x reflected across the plane through a with unit normal n.
TRACER_HD Vec3 reflect_point(Vec3 x, Vec3 a, Vec3 n) { return x - n * (2.0f * dot(x - a, n)); }

struct MirrorImageSample {
  Vec3 wi;                 // unit direction from x to the mirror
  Vec3 mirror_point;       // where wi meets the mirror
  Vec3 wi_light;           // unit direction from the mirror point to the light (wi reflected)
  Vec3 radiance;           // the light's radiance times the mirror's reflectance
  float pdf;               // solid-angle density at x, the image's selection probability included
  uint32_t mirror, light;  // primitive ids
  bool valid;
};

// Solid-angle density with which sample_mirror_image reaches the light point y from x off
// `mirror`, arriving along wi_light at y where the light's normal is ng.
TRACER_HD float mirror_image_pdf(const SceneView& scene, uint32_t mirror, uint32_t light, Vec3 x, Vec3 wi_light, Vec3 y,
                                 Vec3 ng) {
  const Primitive& p = scene.primitives[mirror];
  const Vec3 image_of_x = reflect_point(x, p.a, mirror_normal(p));
  return shape_light_pdf(scene, light, image_of_x, wi_light, length(y - image_of_x), ng) /
         static_cast<float>(scene.mirror_count);
}

// One image sample from x: pick_u picks the light (by the light table), mirror_u the mirror
// (uniformly), (u1, u2) the point on the light. Invalid where the pick is not a shape, the
// light is not on x's side of the plane, or the folded direction misses the mirror.
TRACER_HD MirrorImageSample sample_mirror_image(const SceneView& scene, Vec3 x, float pick_u, float mirror_u, float u1,
                                                float u2) {
  MirrorImageSample s = {};
  s.valid = false;
  const uint32_t entry = pick_light(scene, pick_u);
  if (scene.light_table[entry].kind != LightKind::Shape) return s;
  const uint32_t count = scene.mirror_count;
  s.mirror = scene.mirror_prims[min_of(trunc_to_uint32(mirror_u * static_cast<float>(count)), count - 1u)];
  const Primitive& p = scene.primitives[s.mirror];
  const Vec3 n = mirror_normal(p);
  const float side = dot(x - p.a, n);  // x's signed distance from the plane
  if (side == 0.0f) return s;
  const LightSample ls = sample_light(scene, entry, reflect_point(x, p.a, n), u1, u2, 0.0f);
  if (!ls.valid) return s;
  // From the image of x the ray crosses the plane, at side / along, before the light point.
  const float along = dot(ls.wi, n);
  if (!(side / along > 0.0f && side / along < ls.distance)) return s;
  s.wi = ls.wi - n * (2.0f * along);
  Hit h = {kInfinity, kNoHit, 0.0f, 0.0f};
  const Ray to_mirror = {x, s.wi};
  test_primitive(scene, s.mirror, to_mirror, make_ray_shear(s.wi), h);
  if (h.prim != s.mirror) return s;
  s.mirror_point = ray_at(to_mirror, h.t);
  s.wi_light = ls.wi;
  s.radiance = ls.radiance * mirror_reflectance(scene.materials[p.material], abs_of(along));
  s.pdf = ls.pdf / static_cast<float>(count);
  s.light = ls.emitter;
  s.valid = s.pdf > 0.0f && s.pdf < kInfinity;
  return s;
}

}  // namespace tracer
