// Scale and position: one scene (a Lambert floor, a sphere, a triangle, a point light whose
// intensity scales with s^2 so irradiance is unchanged) scaled by 1e-4 .. 1e4 and moved
// 1e5 from the origin, camera with it, renders the scale-1 image within the tolerances
// below; and a lit Lambert plane has no wrongly shadowed pixel (self-intersection acne) at
// any scale or offset, in the Whitted and the path integrator.
//
// Tolerances (measured, docs/extremes.md): scaled by a power of ten every coordinate
// rounds differently, which moves shading by float rounding only: no pixel may differ by
// more than 1e-3 and the mean difference must stay below 1e-6 (measured 4.7e-8 at 1e-4).
// At 1e5 from the origin every coordinate is quantised to 2^-7 = 0.0078, moving the light
// vector by ~0.2 % and silhouettes by ~0.1 pixel: at most 2 % of pixels may differ by more
// than 0.05 and the mean difference must stay below 0.01 (measured 1.0 % and 0.005).
// These tests guard the scaled ray offsets of kernel/geom/ray_offset.h: the paper's fixed
// 2^-16 near the origin is a third of the sphere at scale 1e-4, its 256 ulps 2 units at 1e5.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "render/render_cpu.h"
#include "test_util.h"

namespace tracer {
namespace {

std::string num(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// A point p of the scale-1 scene, scaled by s and moved by `offset` along (1, 1, 1).
std::string at(double x, double y, double z, double s, double offset) {
  return "[" + num(x * s + offset) + ", " + num(y * s + offset) + ", " + num(z * s + offset) + "]";
}

// A floor tilted to the normal (0.3, 1, 0.2), so its points do not round onto it exactly,
// as a plane, a quad or a triangle, filling the view from above.
std::string tilted_floor(const std::string& kind, double s, double offset) {
  if (kind == "plane")
    return R"({"type": "plane", "point": )" + at(0, 0, 0, s, offset) +
           R"(, "normal": [0.3, 1, 0.2], "material": "floor"})";
  // u = (1, -0.3, 0) and v = (0, -0.2, 1) lie in the floor; cross(v, u) points up.
  if (kind == "quad")
    return R"({"type": "quad", "corner": )" + at(-8, 4, -8, s, offset) + R"(, "u": )" + at(0, -3.2, 16, s, 0) +
           R"(, "v": )" + at(16, -4.8, 0, s, 0) + R"(, "material": "floor"})";
  return R"({"type": "triangle", "vertices": [)" + at(-8, 4, -8, s, offset) + ", " + at(-8, 0.8, 16, s, offset) + ", " +
         at(16, -3.2, -8, s, offset) + R"(], "material": "floor"})";
}

// With occluders: a floor quad, a sphere and a triangle seen from the side. Without: only
// the tilted floor of `floor_kind` seen from above, every pixel on it.
std::string scene(double s, double offset, const std::string& integrator, bool occluders,
                  const std::string& floor_kind = "plane") {
  const std::string shapes =
      (occluders ? R"({"type": "quad", "corner": )" + at(-2, 0, -2, s, offset) + R"(, "u": )" + at(0, 0, 4, s, 0) +
                       R"(, "v": )" + at(4, 0, 0, s, 0) + R"(, "material": "floor"})"
                 : tilted_floor(floor_kind, s, offset)) +
      (occluders
           ? R"(, {"type": "sphere", "center": )" + at(-0.4, 0.5, 0, s, offset) + R"(, "radius": )" + num(0.5 * s) +
                 R"(, "material": "ball"}, {"type": "triangle", "vertices": [)" + at(0.3, 0.1, 0.3, s, offset) + ", " +
                 at(1.1, 0.1, 0.2, s, offset) + ", " + at(0.7, 0.9, -0.2, s, offset) + R"(], "material": "ball"})"
           : "");
  const std::string from = occluders ? at(0, 1.6, 2.6, s, offset) : at(0, 2, 0.5, s, offset);
  const std::string to = occluders ? at(0, 0.3, 0, s, offset) : at(0, 0, 0, s, offset);
  return R"({"format": "tracer-scene/1", "camera": {"from": )" + from + R"(, "to": )" + to + R"(, "vfov": 50},
    "film": {"width": 64, "height": 48},
    "render": {"integrator": ")" +
         integrator + R"(", "spp": 1, "sampler": "center", "max_depth": 1},
    "materials": {"floor": {"type": "lambert", "albedo": [0.8, 0.8, 0.8]}, "ball": {"type": "lambert", "albedo": [0.7, 0.3, 0.2]}},
    "lights": [{"type": "point", "position": )" +
         at(1.5, 3, 1.5, s, offset) + R"(, "intensity": [)" + num(10 * s * s) + ", " + num(10 * s * s) + ", " +
         num(10 * s * s) + R"(]}],
    "shapes": [)" +
         shapes + "]}";
}

Image render(const std::string& json) {
  RenderStats stats;
  Image img = render_cpu(test::scene_from(json), 0, stats);
  EXPECT_EQ(stats.nonfinite_samples + stats.overflow_samples, 0u);
  return img;
}

TEST(ExtremesScale, ScaledScenesRenderTheScaleOneImage) {
  const Image reference = render(scene(1, 0, "whitted", true));
  for (const double s : {1e-4, 1e-2, 1e2, 1e4}) {
    const test::PixelDifferences d = test::pixel_differences(render(scene(s, 0, "whitted", true)), reference);
    std::printf("scale %g: %.4f %% of pixels differ by > 1e-3, mean difference %.3g\n", s, 100 * d.fraction_over(1e-3),
                d.mean());
    EXPECT_EQ(d.count_over(1e-3), 0u) << "scale " << s;
    EXPECT_LE(d.mean(), 1e-6) << "scale " << s;
  }
}

TEST(ExtremesScale, SceneFarFromTheOriginRendersTheSameImage) {
  const Image reference = render(scene(1, 0, "whitted", true));
  const test::PixelDifferences d = test::pixel_differences(render(scene(1, 1e5, "whitted", true)), reference);
  std::printf("offset 1e5: %.4f %% of pixels differ by > 1e-3, %.4f %% by > 0.05, mean difference %.3g\n",
              100 * d.fraction_over(1e-3), 100 * d.fraction_over(5e-2), d.mean());
  EXPECT_LE(d.fraction_over(5e-2), 0.02);
  EXPECT_LE(d.mean(), 0.01);
}

// Every pixel sees the floor lit by the light; one that reads 0 was shadowed by the floor
// itself. The floor as a plane, a quad and a triangle, each with its own ray test.
TEST(ExtremesScale, LitFloorHasNoAcneAtAnyScale) {
  for (const char* kind : {"plane", "quad", "triangle"})
    for (const char* integrator : {"whitted", "path"})
      for (const double s : {1e-4, 1e-2, 1.0, 1e2, 1e4})
        for (const double offset : {0.0, 1e5 * s}) {
          const Image img = render(scene(s, offset, integrator, false, kind));
          int dark = 0;
          for (size_t i = 0; i < img.rgb.size(); i += 3) dark += !(img.rgb[i] > 0.0f);
          EXPECT_EQ(dark, 0) << kind << ", " << integrator << " at scale " << s << ", offset " << offset;
        }
}

}  // namespace
}  // namespace tracer
