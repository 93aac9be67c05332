// Textures as plain data: images decoded once on the host into linear float RGB texels, and
// the procedural checker. Sampled by our own bilinear filter (plain + - * and floor), so the
// CPU and CUDA read the same values. Texture space: u to the right, v up; texel (x, y) has
// its centre at u = (x + 0.5) / width, v = 1 - (y + 0.5) / height (row 0 is the image's top).
#pragma once
#include "kernel/base/float_to_int.h"
#include "kernel/base/platform.h"
#include "kernel/base/vec3.h"

namespace tracer {

constexpr uint32_t kNoTexture = 0xffffffffu;

enum class TextureKind : uint32_t { Image, Checker };
enum class TextureWrap : uint32_t { Repeat, Clamp, Mirror };  // Mirror: glTF's MIRRORED_REPEAT

struct Texture {
  TextureKind kind;
  TextureWrap wrap_u, wrap_v;  // along u (the image's x) and v (its y)
  uint32_t width, height;
  uint32_t offset;   // image: its texels start at texels[offset], 3 floats each, row by row
  Vec3 times, plus;  // image: its filtered value times `times` plus `plus`, so images tinted or
                     // scaled differently share their texels (glTF's factors, a normal map's scale)
  Vec3 even, odd;    // checker: colour where floor(u s) + floor(v s) is even / odd
  float scale;       // checker: squares per unit of u and v
};

// An image texture of width x height texels from texels[offset], read as they are.
TRACER_HD Texture image_texture(uint32_t width, uint32_t height, uint32_t offset, TextureWrap wrap_u,
                                TextureWrap wrap_v) {
  Texture t{};
  t.kind = TextureKind::Image;
  t.wrap_u = wrap_u, t.wrap_v = wrap_v;
  t.width = width, t.height = height;
  t.offset = offset;
  t.times = {1.0f, 1.0f, 1.0f};
  return t;
}

// The bilinear filter's texel index, in [-1, n] once its coordinate is wrapped into [0, 1]:
// past an edge, repeat reads the opposite edge; clamp and mirror read the edge texel itself
// (a mirrored copy begins with the texel it ends on).
TRACER_HD int wrap_texel(int i, int n, TextureWrap wrap) {
  if (i >= 0 && i < n) return i;
  if (wrap == TextureWrap::Repeat) return i < 0 ? n - 1 : 0;
  return i < 0 ? 0 : n - 1;
}

TRACER_HD Vec3 texel_at(const float* texels, const Texture& t, int x, int y) {
  const float* p = texels + t.offset +
                   3u * (static_cast<uint32_t>(wrap_texel(y, t.height, t.wrap_v)) * t.width +
                         static_cast<uint32_t>(wrap_texel(x, t.width, t.wrap_u)));
  return {p[0], p[1], p[2]};
}

// A texture coordinate into [0, 1]: its fraction (repeat), the nearest edge (clamp), or its
// distance into a period of 2 folded back past 1 (mirror); NaN becomes 0.
TRACER_HD float wrap_coordinate(float c, TextureWrap wrap) {
  c = c == c ? c : 0.0f;
  if (wrap == TextureWrap::Clamp) return c < 0.0f ? 0.0f : (c > 1.0f ? 1.0f : c);
  if (wrap == TextureWrap::Repeat) return c - floorf(c);
  const float f = c - 2.0f * floorf(c * 0.5f);
  return f > 1.0f ? 2.0f - f : f;
}

// Bilinear filter as two linear interpolations along x, then one along y, each a + (b - a) f,
// then the image's times and plus: a constant texture returns its value exactly, and a texel
// centre (f = 0) its texel, each times 1 plus 0 unless the texture says otherwise.
TRACER_HD Vec3 sample_texture(const Texture* textures, const float* texels, uint32_t index, float u, float v) {
  const Texture& t = textures[index];
  if (t.kind == TextureKind::Checker) {
    if (!(abs_of(u * t.scale) < 0x1p23f && abs_of(v * t.scale) < 0x1p23f))
      return t.even;  // NaN or beyond float's integers
    const float cu = floorf(u * t.scale), cv = floorf(v * t.scale);
    const float parity = cu + cv - 2.0f * floorf((cu + cv) * 0.5f);
    return parity == 0.0f ? t.even : t.odd;
  }
  // Into [0, 1] first, so texel indices stay small whatever the coordinates.
  u = wrap_coordinate(u, t.wrap_u);
  v = wrap_coordinate(v, t.wrap_v);
  const float x = u * static_cast<float>(t.width) - 0.5f, y = (1.0f - v) * static_cast<float>(t.height) - 0.5f;
  const float x0 = floorf(x), y0 = floorf(y);
  const float fx = x - x0, fy = y - y0;
  const int ix = trunc_to_int32(x0), iy = trunc_to_int32(y0);
  const Vec3 t00 = texel_at(texels, t, ix, iy), t10 = texel_at(texels, t, ix + 1, iy);
  const Vec3 t01 = texel_at(texels, t, ix, iy + 1), t11 = texel_at(texels, t, ix + 1, iy + 1);
  const Vec3 top = t00 + (t10 - t00) * fx, bottom = t01 + (t11 - t01) * fx;
  return (top + (bottom - top) * fy) * t.times + t.plus;
}

}  // namespace tracer
