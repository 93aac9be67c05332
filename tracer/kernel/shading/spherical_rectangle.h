// Solid-angle sampling of a rectangular light (Urena, Fajardo and King 2013, "An Area-Preserving
// Parametrization for Spherical Rectangles", EGSR): directions uniform in the solid angle the
// rectangle subtends from a point. Sampling by area divides by the density's conversion to
// solid angle, cos / d^2, whose spike beside a lamp was most of a Cornell box's noise.
//
// The rectangle is corner + s edge_u + t edge_v for (s, t) in [0, 1]^2, its edges perpendicular.
// Where the parametrization loses its precision in float, the light is sampled by area
// instead (kernel/shading/solid_angle.h): a parallelogram, and solid angles outside the range
// sampled that way.
#pragma once
#include "kernel/base/vec3.h"
#include "kernel/shading/solid_angle.h"

namespace tracer {

// |cos| of the angle between the edges above which a quad is a parallelogram, not a rectangle.
constexpr float kRectangleEdgeCosine = 1e-5f;

// The paper's setup: the rectangle in a frame at the point, x and y along its edges, z towards
// the point's side of its plane, so that it spans [x0, x1] x [y0, y1] at height z0 < 0.
struct SphericalRectangle {
  float x0, x1, y0, y1, z0;
  float b0, b1, k;    // the normals' z of the first and third edge planes; 2 pi minus two angles
  float solid_angle;  // in steradians; 0 where the light is sampled by area
};

TRACER_HD SphericalRectangle spherical_rectangle(Vec3 from, Vec3 corner, Vec3 edge_u, Vec3 edge_v) {
  SphericalRectangle r = {0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  const float lu = length(edge_u), lv = length(edge_v);
  if (!(lu > 0.0f && lv > 0.0f)) return r;
  const Vec3 x = edge_u / lu, y = edge_v / lv;
  if (!(abs_of(dot(x, y)) <= kRectangleEdgeCosine)) return r;
  const Vec3 d = corner - from;
  const float z = dot(d, cross(x, y));
  r.x0 = dot(d, x), r.y0 = dot(d, y), r.z0 = -abs_of(z);
  r.x1 = r.x0 + lu, r.y1 = r.y0 + lv;
  // The planes through the point and each edge have the normals n0 = (0, z0, -y0) / |(y0, z0)|,
  // n1 = (-z0, 0, x1) / |(x1, z0)|, n2 = (0, -z0, y1) / |(y1, z0)|, n3 = (z0, 0, -x0) / |(x0, z0)|
  // (the paper's normalize(cross(v00, v10)) and so on, with the corners' common coordinates
  // cancelled); the spherical rectangle's interior angles are acos(-n_i . n_i+1), and its area
  // (Girard) is their sum minus 2 pi.
  const float z2 = r.z0 * r.z0;
  const float dx0 = det_sqrt(r.x0 * r.x0 + z2), dx1 = det_sqrt(r.x1 * r.x1 + z2);
  const float dy0 = det_sqrt(r.y0 * r.y0 + z2), dy1 = det_sqrt(r.y1 * r.y1 + z2);
  const float g0 = solid_angle_acos(clamp_of(r.y0 * r.x1 / (dy0 * dx1), -1.0f, 1.0f));
  const float g1 = solid_angle_acos(clamp_of(-r.x1 * r.y1 / (dx1 * dy1), -1.0f, 1.0f));
  const float g2 = solid_angle_acos(clamp_of(r.x0 * r.y1 / (dy1 * dx0), -1.0f, 1.0f));
  const float g3 = solid_angle_acos(clamp_of(-r.x0 * r.y0 / (dx0 * dy0), -1.0f, 1.0f));
  r.b0 = -r.y0 / dy0, r.b1 = r.y1 / dy1;
  r.k = 2.0f * kPi - g2 - g3;
  const float solid_angle = g0 + g1 - r.k;
  r.solid_angle = sampled_solid_angle(solid_angle);
  return r;
}

// The rectangle's parameters (s, t) of the direction that (u, v) in [0, 1)^2 maps to, uniformly
// in solid angle (the paper's algorithm 1: u picks the azimuthal slab by its area, v the
// height in it); for a rectangle with solid_angle > 0.
TRACER_HD void sample_spherical_rectangle(const SphericalRectangle& r, float u, float v, float& s, float& t) {
  float sin_au, cos_au;
  det_sincos(u * r.solid_angle + r.k, sin_au, cos_au);
  const float fu = (cos_au * r.b0 - r.b1) / sin_au;
  const float cu = clamp_of((fu > 0.0f ? 1.0f : -1.0f) / det_sqrt(fu * fu + r.b0 * r.b0), -1.0f, 1.0f);
  const float xu = clamp_of(-(cu * r.z0) / det_sqrt(max_of(1.0f - cu * cu, 0.0f)), r.x0, r.x1);
  const float dist = det_sqrt(xu * xu + r.z0 * r.z0);
  const float h0 = r.y0 / det_sqrt(dist * dist + r.y0 * r.y0);
  const float h1 = r.y1 / det_sqrt(dist * dist + r.y1 * r.y1);
  const float hv = h0 + v * (h1 - h0), hv2 = hv * hv;
  const float yv = hv2 < 1.0f - 1e-6f ? hv * dist / det_sqrt(1.0f - hv2) : r.y1;
  s = clamp_of((xu - r.x0) / (r.x1 - r.x0), 0.0f, 1.0f);
  t = clamp_of((yv - r.y0) / (r.y1 - r.y0), 0.0f, 1.0f);
}

}  // namespace tracer
