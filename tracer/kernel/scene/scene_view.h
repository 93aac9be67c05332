// The scene as kernel code sees it: plain pointers to flat arrays, filled on the host or
// copied to the device, and the primitive test every acceleration structure calls
// (kernel/accel/trace.h dispatches the queries). The closest hit is the minimum of
// (t, primitive id) compared lexicographically (docs/determinism.md rule 4).
#pragma once
#include "kernel/accel/bvh_node.h"
#include "kernel/accel/bvh_pair_node.h"
#include "kernel/accel/grid.h"
#include "kernel/accel/kd_node.h"
#include "kernel/accel/wide_bvh_node.h"
#include "kernel/base/features.h"
#include "kernel/camera/camera.h"
#include "kernel/camera/sampler.h"
#include "kernel/geom/primitive.h"
#include "kernel/light/light_records.h"
#include "kernel/material/material.h"
#include "kernel/scene/render_settings.h"
#include "kernel/scene/scene_arrays.h"

namespace tracer {

struct SceneView {
#define TRACER_VIEW_POINTER(Type, name) const Type* name;
  TRACER_SCENE_ARRAYS(TRACER_VIEW_POINTER)  // kernel/scene/scene_arrays.h
#undef TRACER_VIEW_POINTER
  uint32_t primitive_count;
  uint32_t bounded_count;
  uint32_t unbounded_count;
  uint32_t bvh_node_count;
  uint32_t bvh_pair_count;  // 0 unless the GPU's walk records were built (cuda/device_scene.h)
  uint32_t wide_node_count;
  uint32_t kd_node_count;
  uint32_t light_count;
  uint32_t light_entry_count;
  uint32_t mirror_count;  // mirror_prims' length: 0 unless render.mirror_images finds planar mirrors
  Vec3 kd_lo, kd_hi;      // the kd-tree's box
  float kd_pad;           // as GridInfo::pad
  GridInfo grid;
  uint32_t sky_cell_columns;    // the environment's cells (environment_light.h): per cube face, or on
  uint32_t sky_cell_rows;       // the equirectangular map; 0 when it is not sampled
  uint32_t environment_light;   // the environment's light_table entry, or kNoHit
  float offset_scale;           // ray offsets near the origin (kernel/geom/ray_offset.h): a power of two <= 1
  Background background;
  Vec3 ambient;
  Camera camera;
  RenderSettings settings;
  uint32_t features;  // FeatureBit mask
};

constexpr uint32_t kNoHit = 0xffffffffu;  // no primitive, light or table entry

}  // namespace tracer
