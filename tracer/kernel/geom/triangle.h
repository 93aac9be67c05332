// Watertight ray/triangle intersection (Woop, Benthin, Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013): the ray is sheared so it runs along +z, and the 2D edge
// functions are evaluated so that a point on a shared edge is inside both triangles;
// edge functions that come out exactly 0 are recomputed in double, as the paper does.
#pragma once
#include <glm/gtc/type_ptr.hpp>

#include "kernel/base/vec3.h"

namespace tracer {

// The per-ray part of the test: the dominant axis and the shear.
struct RayShear {
  int kx, ky, kz;
  float sx, sy, sz;
};

TRACER_HD RayShear make_ray_shear(Vec3 d) {
  const float ax = abs_of(d.x), ay = abs_of(d.y), az = abs_of(d.z);
  RayShear s;
  s.kz = (ax > ay) ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
  s.kx = s.kz == 2 ? 0 : s.kz + 1;
  s.ky = s.kx == 2 ? 0 : s.kx + 1;
  if (d[s.kz] < 0.0f) {  // keep the winding: swap x and y
    const int t = s.kx;
    s.kx = s.ky;
    s.ky = t;
  }
  s.sx = d[s.kx] / d[s.kz];
  s.sy = d[s.ky] / d[s.kz];
  s.sz = 1.0f / d[s.kz];
  return s;
}

// On a hit writes t and the barycentric weights (b0, b1, b2) of v0, v1, v2.
TRACER_HD bool intersect_triangle(const Vec3& v0, const Vec3& v1, const Vec3& v2, const Ray& ray, const RayShear& s,
                                  float tmin, float tmax, float& t_out, float& b0, float& b1, float& b2) {
  // The vertices relative to the origin, permuted to (kx, ky, kz). A vertex is read through
  // its address (GLM's value_ptr), so the GPU loads the three components it needs instead of
  // holding all nine to select from: the trace kernels then fit 64 registers (docs/cuda.md).
  const float ox = ray.origin[s.kx], oy = ray.origin[s.ky], oz = ray.origin[s.kz];
  const float *p0 = glm::value_ptr(v0), *p1 = glm::value_ptr(v1), *p2 = glm::value_ptr(v2);
  const Vec3 a = {p0[s.kx] - ox, p0[s.ky] - oy, p0[s.kz] - oz};
  const Vec3 b = {p1[s.kx] - ox, p1[s.ky] - oy, p1[s.kz] - oz};
  const Vec3 c = {p2[s.kx] - ox, p2[s.ky] - oy, p2[s.kz] - oz};
  const float ax = a.x - s.sx * a.z, ay = a.y - s.sy * a.z;
  const float bx = b.x - s.sx * b.z, by = b.y - s.sy * b.z;
  const float cx = c.x - s.sx * c.z, cy = c.y - s.sy * c.z;
  float u = cx * by - cy * bx;
  float v = ax * cy - ay * cx;
  float w = bx * ay - by * ax;
  if (u == 0.0f || v == 0.0f || w == 0.0f) {
    u = static_cast<float>(static_cast<double>(cx) * by - static_cast<double>(cy) * bx);
    v = static_cast<float>(static_cast<double>(ax) * cy - static_cast<double>(ay) * cx);
    w = static_cast<float>(static_cast<double>(bx) * ay - static_cast<double>(by) * ax);
  }
  if ((u < 0.0f || v < 0.0f || w < 0.0f) && (u > 0.0f || v > 0.0f || w > 0.0f)) return false;
  const float det = u + v + w;
  if (det == 0.0f) return false;
  const float az = s.sz * a.z, bz = s.sz * b.z, cz = s.sz * c.z;
  const float t_scaled = u * az + v * bz + w * cz;
  const float t = t_scaled / det;
  if (!(t > tmin && t <= tmax)) return false;
  // Reject t not conservatively above 0 (pbrt-v4 section 6.8.6's bound on t's error). The
  // sheared x' = x - sx z carries the error of its two terms, gamma(3) (|x'| + 2 |sx z|);
  // pbrt bounds |sx z| by the scaled |z / d_z|, which for a ray nearly in a sliver's plane
  // is 1e5 times too loose and rejected its true hits (tests/extremes/test_extremes_degenerate.cpp).
  const float max_zt = max_of(abs_of(az), max_of(abs_of(bz), abs_of(cz)));
  const float max_xt = max_of(abs_of(ax), max_of(abs_of(bx), abs_of(cx)));
  const float max_yt = max_of(abs_of(ay), max_of(abs_of(by), abs_of(cy)));
  const float max_z = max_of(abs_of(a.z), max_of(abs_of(b.z), abs_of(c.z)));
  const float delta_z = error_gamma(3) * max_zt;
  const float delta_x = error_gamma(5) * (max_xt + 2.0f * abs_of(s.sx) * max_z);
  const float delta_y = error_gamma(5) * (max_yt + 2.0f * abs_of(s.sy) * max_z);
  const float delta_e = 2.0f * (error_gamma(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
  const float max_e = max_of(abs_of(u), max_of(abs_of(v), abs_of(w)));
  const float delta_t = 3.0f * (error_gamma(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) / abs_of(det);
  if (!(t > delta_t)) return false;
  t_out = t;
  b0 = u / det;
  b1 = v / det;
  b2 = w / det;
  return true;
}

}  // namespace tracer
