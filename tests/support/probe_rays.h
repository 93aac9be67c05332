// Rays that probe a scene's acceleration structure where structures could disagree: random
// rays through the scene's box, and rays aimed at triangles' and quads' vertices and edge
// midpoints (where neighbours tie at equal t) from random origins.
#pragma once
#include <vector>

#include "scene/scene.h"
#include "test_util.h"

namespace tracer::test {

inline std::vector<Ray> probe_rays(const Scene& scene) {
  InputStream s{5};
  Vec3 lo = {kInfinity, kInfinity, kInfinity}, hi = -lo;
  for (const Primitive& p : scene.primitives)
    if (p.kind != ShapeKind::Plane) lo = min_of(lo, min_of(p.a, p.c)), hi = max_of(hi, max_of(p.a, p.c));
  if (!(lo.x <= hi.x)) lo = {-1, -1, -1}, hi = {1, 1, 1};
  const Vec3 size = hi - lo;
  const auto point = [&] {
    return lo - size * 0.25f + Vec3{s.next() * size.x, s.next() * size.y, s.next() * size.z} * 1.5f;
  };
  std::vector<Ray> rays;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 o = point(), t = point();
    if (!(length(t - o) > 0)) continue;
    rays.push_back({o, normalize(t - o)});
  }
  for (const Primitive& p : scene.primitives) {
    if (p.kind != ShapeKind::Triangle && p.kind != ShapeKind::Quad) continue;
    const Vec3 b = p.kind == ShapeKind::Quad ? p.a + p.b : p.b, c = p.kind == ShapeKind::Quad ? p.a + p.c : p.c;
    for (const Vec3 target : {p.a, b, c, (p.a + b) * 0.5f, (b + c) * 0.5f, (c + p.a) * 0.5f}) {
      const Vec3 o = point();
      if (length(target - o) > 0) rays.push_back({o, normalize(target - o)});
    }
  }
  return rays;
}

}  // namespace tracer::test
