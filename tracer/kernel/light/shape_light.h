// An emissive sphere, quad or triangle as a light (emissive planes are infinite and only found by
// chance). Spheres seen from outside are sampled uniformly in the cone they subtend; with
// render.light_sampling "solid-angle", quads and triangles uniformly in their solid angle
// (kernel/shading/spherical_rectangle.h, spherical_triangle.h); other shapes, and quads and
// triangles by default or where float cannot sample their solid angle, uniformly by area. The
// sample's point is where its radiance texture, if any, is read.
#pragma once
#include "kernel/light/light_records.h"
#include "kernel/shading/sampling.h"
#include "kernel/shading/spherical_rectangle.h"
#include "kernel/shading/spherical_triangle.h"
#include "kernel/shading/surface.h"

namespace tracer {

TRACER_HD float primitive_area(const Primitive& p) {
  switch (p.kind) {
    case ShapeKind::Sphere: return 4.0f * kPi * p.radius * p.radius;
    case ShapeKind::Quad: return length(cross(p.b, p.c));
    case ShapeKind::Triangle: return 0.5f * length(cross(p.b - p.a, p.c - p.a));
    case ShapeKind::Plane: break;
  }
  return 0.0f;
}

// 1 - cos(theta_max) of the cone a sphere subtends from a point outside it, as
// x / (1 + sqrt(1 - x)) with x = r^2 / d^2: no cancellation for distant, small spheres.
// 0 when the sphere is too small to be sampled from there.
TRACER_HD float sphere_cone_width(const Primitive& p, float dist2) {
  const float x = min_of(p.radius * p.radius / dist2, 1.0f);
  return x / (1.0f + det_sqrt(1.0f - x));
}

// Solid-angle density of sampling the point at distance t along unit wi on emitter `prim`
// with geometric normal ng, seen from `from` (selection probability included); 0 for a
// primitive that is not in the light table.
TRACER_HD float shape_light_pdf(const SceneView& scene, uint32_t prim, Vec3 from, Vec3 wi, float t, Vec3 ng) {
  const uint32_t entry = scene.light_of_prim[prim];
  if (entry == kNoHit) return 0.0f;
  const Primitive& p = scene.primitives[prim];
  const float pmf = scene.light_table[entry].pmf;
  if (p.kind == ShapeKind::Sphere) {
    const Vec3 to_center = p.a - from;
    const float d2 = dot(to_center, to_center);
    if (d2 > p.radius * p.radius) {
      const float width = sphere_cone_width(p, d2);
      return width > 0.0f ? pmf / (2.0f * kPi * width) : 0.0f;
    }
  }
  if (p.kind == ShapeKind::Quad && scene.settings.light_sampling == LightSampling::SolidAngle) {
    const SphericalRectangle rect = spherical_rectangle(from, p.a, p.b, p.c);
    if (rect.solid_angle > 0.0f) return pmf / rect.solid_angle;
  }
  if (p.kind == ShapeKind::Triangle && scene.settings.light_sampling == LightSampling::SolidAngle) {
    const float omega = spherical_triangle(from, p.a, p.b, p.c).solid_angle;
    if (omega > 0.0f) return pmf / omega;
  }
  const float cos_l = abs_of(dot(ng, wi));
  return cos_l > 0.0f ? pmf * t * t / (cos_l * primitive_area(p)) : 0.0f;
}

// A sample of the shape light `entry` seen from `from`, by (u1, u2).
TRACER_HD LightSample sample_shape_light(const SceneView& scene, const LightEntry& entry, Vec3 from, float u1,
                                         float u2) {
  LightSample s = {{0.0f, 0.0f, 0.0f}, 0.0f, {0.0f, 0.0f, 0.0f}, 0.0f, LightKind::Shape, false, entry.index, false};
  const Primitive& p = scene.primitives[entry.index];
  Vec3 point = {0.0f, 0.0f, 0.0f}, ng = {0.0f, 0.0f, 0.0f};  // every shape case sets both
  float b1 = 0.0f, b2 = 0.0f;  // the sampled point's quad or triangle parameters, for its texture lookup
  float solid_angle = 0.0f;    // > 0 where sampled uniformly in solid angle: shape_light_pdf's pmf / solid_angle
  switch (p.kind) {
    case ShapeKind::Sphere: {
      const Vec3 to_center = p.a - from;
      const float d2 = dot(to_center, to_center);
      if (d2 > p.radius * p.radius) {
        const Vec3 axis = to_center / det_sqrt(d2);
        const float width = sphere_cone_width(p, d2);
        if (!(width > 0.0f)) return s;
        s.wi = frame_around(axis).to_world(sample_cone(width, u1, u2));
        float t = 0.0f;
        // A direction on the cone's rim grazes the sphere, and rounding can make the ray miss
        // it (a discriminant just below 0): the point of closest approach is then the tangent
        // point, within rounding of the surface. (u1, u2) = (0.99999923, 0.83403116) from
        // (0.4, 1.2, 2) towards a sphere of radius 0.5 at the origin is such a direction.
        if (!intersect_sphere(p.a, p.radius, {from, s.wi}, 0.0f, kInfinity, t)) t = dot(to_center, s.wi);
        point = from + s.wi * t;
      } else {
        point = p.a + direction_from(1.0f - 2.0f * u1, u2) * p.radius;  // uniform on the sphere
      }
      ng = normalize(point - p.a);
      break;
    }
    case ShapeKind::Quad: {
      b1 = u1, b2 = u2;
      if (scene.settings.light_sampling == LightSampling::SolidAngle) {
        const SphericalRectangle rect = spherical_rectangle(from, p.a, p.b, p.c);
        solid_angle = rect.solid_angle;
        if (solid_angle > 0.0f) sample_spherical_rectangle(rect, u1, u2, b1, b2);
      }
      point = p.a + p.b * b1 + p.c * b2;
      ng = normalize(cross(p.b, p.c));
      break;
    }
    case ShapeKind::Triangle: {
      if (scene.settings.light_sampling == LightSampling::SolidAngle) {
        const SphericalTriangle tri = spherical_triangle(from, p.a, p.b, p.c);
        solid_angle = tri.solid_angle;
        if (solid_angle > 0.0f) sample_spherical_triangle(tri, from, p.a, p.b, p.c, u1, u2, b1, b2);
      }
      if (!(solid_angle > 0.0f)) sample_triangle(u1, u2, b1, b2);
      point = p.a * (1.0f - b1 - b2) + p.b * b1 + p.c * b2;
      ng = normalize(cross(p.b - p.a, p.c - p.a));
      break;
    }
    case ShapeKind::Plane: return s;
  }
  const Vec3 to_point = point - from;
  s.distance = length(to_point);
  if (!(s.distance > 0.0f)) return s;
  s.wi = to_point / s.distance;
  const Material& m = scene.materials[p.material];
  const bool front = dot(s.wi, ng) < 0.0f;  // the light's front faces the shading point
  if (!front && !m.two_sided) return s;
  if (m.texture[kSlotRadiance] == kNoTexture) {
    s.radiance = m.radiance;
  } else {
    Surface at = surface_at(scene, {from, s.wi}, {s.distance, entry.index, b1, b2});
    s.radiance = material_at(scene, at).radiance;
  }
  s.pdf =
      solid_angle > 0.0f ? entry.pmf / solid_angle : shape_light_pdf(scene, entry.index, from, s.wi, s.distance, ng);
  s.valid = s.pdf > 0.0f && s.pdf < kInfinity;
  return s;
}

// The power that chooses it in the light table: pi L A, twice for a two-sided emitter.
inline double shape_light_power(const Primitive& p, const Material& m) {
  return kPi * luminance(m.radiance) * primitive_area(p) * (m.two_sided ? 2.0 : 1.0);
}

}  // namespace tracer
