// Next-event estimation's light choice and light sampling for the path integrator. The
// host builds a table of every light (point lights and emissive spheres, quads and
// triangles; emissive planes are infinite and only found by chance; a cube-map sky when
// render.sky_sampling is on) with a selection probability proportional to its power
// (tracer/light_table.cpp). Spheres seen from outside are sampled uniformly in the cone they
// subtend; with render.light_sampling "solid-angle", rectangles and triangles uniformly in their
// solid angle (kernel/shading/spherical_rectangle.h, spherical_triangle.h); other shapes, and
// rectangles and triangles by default or where float cannot sample their solid angle,
// uniformly by area; the sky by its cells (kernel/shading/sky_sampling.h).
#pragma once
#include "kernel/shading/light_sources.h"
#include "kernel/shading/sampling.h"
#include "kernel/shading/sky_sampling.h"
#include "kernel/shading/spherical_rectangle.h"
#include "kernel/shading/spherical_triangle.h"
#include "kernel/shading/surface.h"

namespace tracer {

struct LightSample {
  Vec3 wi;         // unit direction from the shading point to the light
  float distance;  // to the sampled point (point lights: to the light)
  Vec3 radiance;   // arriving at the shading point if unoccluded (point lights: I x falloff)
  float pdf;       // solid-angle density including the selection probability; the
                   // selection probability alone for a point light (delta)
  uint32_t prim;   // the emitting primitive, kNoHit for a point light, kSkyLight for the sky
  bool valid;
};

TRACER_HD uint32_t pick_light(const SceneView& scene, float u) {
  return find_cdf_interval(scene.light_table, scene.light_entry_count, u);
}

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
// with geometric normal ng, seen from `from` (selection probability included).
TRACER_HD float light_pdf(const SceneView& scene, uint32_t prim, Vec3 from, Vec3 wi, float t, Vec3 ng) {
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

// Solid-angle density with which NEE draws sky direction dir (selection probability included).
TRACER_HD float sky_light_pdf(const SceneView& scene, Vec3 dir) {
  if (scene.sky_light == kNoHit) return 0.0f;
  return scene.light_table[scene.sky_light].pmf * sky_direction_pdf(scene, dir);
}

// A sample of light entry_index seen from `from`, by (u1, u2) and, for the sky's cell, cell_u.
TRACER_HD LightSample sample_light(const SceneView& scene, uint32_t entry_index, Vec3 from, float u1, float u2,
                                   float cell_u) {
  const LightEntry& entry = scene.light_table[entry_index];
  LightSample s = {{0.0f, 0.0f, 0.0f}, 0.0f, {0.0f, 0.0f, 0.0f}, 0.0f, kNoHit, false};
  if (entry.kind == LightKind::Sky) {
    s.wi = sample_sky_direction(scene, cell_u, u1, u2);
    s.distance = kInfinity;
    s.radiance = background_radiance(scene, s.wi);
    s.prim = kSkyLight;
    s.pdf = sky_light_pdf(scene, s.wi);
    s.valid = s.pdf > 0.0f && s.pdf < kInfinity;
    return s;
  }
  if (entry.kind == LightKind::Point) {
    const PointLight& light = scene.lights[entry.index];
    const Vec3 to_light = light.position - from;
    const float d2 = dot(to_light, to_light);
    s.distance = det_sqrt(d2);
    if (!(s.distance > 0.0f)) return s;
    s.wi = to_light / s.distance;
    s.radiance = light.intensity * light_falloff(light, s.distance, d2);
    s.pdf = entry.pmf;
    s.valid = true;
    return s;
  }
  const Primitive& p = scene.primitives[entry.index];
  s.prim = entry.index;
  Vec3 point = {0.0f, 0.0f, 0.0f}, ng = {0.0f, 0.0f, 0.0f};  // every shape case sets both
  float b1 = 0.0f, b2 = 0.0f;  // the sampled point's quad or triangle parameters, for its texture lookup
  float solid_angle = 0.0f;    // > 0 where sampled uniformly in solid angle: light_pdf's pmf / solid_angle
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
  s.pdf = solid_angle > 0.0f ? entry.pmf / solid_angle : light_pdf(scene, entry.index, from, s.wi, s.distance, ng);
  s.valid = s.pdf > 0.0f && s.pdf < kInfinity;
  return s;
}

}  // namespace tracer
