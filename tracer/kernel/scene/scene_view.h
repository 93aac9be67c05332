// The scene as kernel code sees it: plain pointers to flat arrays, filled on the host or
// copied to the device, and the primitive test every acceleration structure calls
// (kernel/accel/trace.h dispatches the queries). The closest hit is the minimum of
// (t, primitive id) compared lexicographically (docs/determinism.md rule 4).
#pragma once
#include "kernel/accel/bvh_node.h"
#include "kernel/accel/grid.h"
#include "kernel/accel/kd_node.h"
#include "kernel/accel/wide_bvh_node.h"
#include "kernel/base/features.h"
#include "kernel/camera/camera.h"
#include "kernel/camera/sampler.h"
#include "kernel/geom/primitive.h"
#include "kernel/scene/render_settings.h"
#include "kernel/scene/scene_arrays.h"
#include "kernel/shading/material.h"

namespace tracer {

enum class BackgroundKind : uint32_t { Constant, Gradient, Cubemap };

struct PointLight {
  Vec3 position;
  Vec3 intensity;
  float kc, kl, kq;          // attenuation, used when has_attenuation
  uint32_t has_attenuation;  // 0: physical 1/d^2 falloff
};

// An entry of the path integrator's light table (kernel/shading/light_sampling.h).
enum class LightKind : uint32_t { Point, Shape, Sky };
struct LightEntry {
  LightKind kind;
  uint32_t index;  // into SceneView::lights, or the emitting primitive's id; 0 for the sky
  float pmf;       // probability of choosing this light
  float cdf;       // sum of the pmfs up to and including this entry; 1 for the last
};

// A cell of a cube-map sky's sampling distribution (kernel/shading/sky_sampling.h).
struct SkyCell {
  float pmf;  // probability of drawing the cell, a multiple of 2^-24
  float cdf;  // sum of the pmfs up to and including this cell; 1 for the last
};

struct Background {
  BackgroundKind kind;
  Vec3 radiance;      // constant; the zenith colour for gradient
  Vec3 horizon;       // gradient only
  uint32_t faces[6];  // cubemap: textures of the faces +x, -x, +y, -y, +z, -z
};

struct SceneView {
#define TRACER_VIEW_POINTER(Type, name) const Type* name;
  TRACER_SCENE_ARRAYS(TRACER_VIEW_POINTER)  // kernel/scene/scene_arrays.h
#undef TRACER_VIEW_POINTER
  uint32_t primitive_count;
  uint32_t bounded_count;
  uint32_t unbounded_count;
  uint32_t bvh_node_count;
  uint32_t wide_node_count;
  uint32_t kd_node_count;
  uint32_t light_count;
  uint32_t light_entry_count;
  uint32_t mirror_count;  // mirror_prims' length: 0 unless render.mirror_images finds planar mirrors
  Vec3 kd_lo, kd_hi;  // the kd-tree's box
  float kd_pad;       // as GridInfo::pad
  GridInfo grid;
  uint32_t sky_cells_per_side;  // n
  uint32_t sky_light;           // the sky's light_table entry, or kNoHit
  float offset_scale;           // ray offsets near the origin (kernel/geom/ray_offset.h): a power of two <= 1
  Background background;
  Vec3 ambient;
  Camera camera;
  RenderSettings settings;
  uint32_t features;  // FeatureBit mask
};

constexpr uint32_t kNoHit = 0xffffffffu;  // no primitive, light or table entry

}  // namespace tracer
