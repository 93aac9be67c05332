// The stream schedule (render.schedule stream): the GPU stream ray tracer's design, and
// pbrt-v4's wavefront integrator. A batch of pixel samples lives as ray states in arrays (a
// structure of arrays, one entry per sample), and each stage is a function of one state that
// a scheduler calls over a queue of state indices: the OpenMP loop of
// tracer/render/render_stream.cpp, or a CUDA grid. The stages call the megakernel's own
// steps (path_shade, trace_shadows, whitted_begin, ...) in the megakernel's order for each
// state, and every random number is a function of (pixel, sample, dimension), so a sample's
// radiance is the megakernel's bit for bit however the queues are ordered; the host adds the
// batch's samples to the film in pixel-sample order (film.h's sums saturate near 2^62).
#pragma once
#include "kernel/integrator/render_pixel.h"
#include "kernel/integrator/stream_stage.h"
#include "kernel/integrator/stream_target.h"

namespace tracer {

// The ray states of one batch. Arrays an integrator does not use may be null.
struct StreamStates {
  uint32_t* pixel;  // y * width + x
  uint32_t* sample;
  Vec3* origin;  // the ray to trace
  Vec3* dir;
  Hit* hit;  // its closest hit
  Vec3* radiance;
  uint8_t* next;
  // the path tracer's state between bounces (PathState: TRACER_PATH_STATE in path.h)
#define TRACER_PATH_ARRAY(Type, Stored, name, initial) Stored* name;
  TRACER_PATH_STATE(TRACER_PATH_ARRAY)
#undef TRACER_PATH_ARRAY
  // the shadow ray (ShadowQuery; Whitted's has emitter kNoHit and no contribution)
  Vec3* shadow_origin;
  Vec3* shadow_dir;
  float* shadow_tmax;
  uint32_t* shadow_emitter;
  Vec3* shadow_contribution;
  // the path's shadow queries (ShadowKind bits) and its mirror-image query, where the scene
  // lists flat mirrors (SceneView::mirror_count > 0); without them the shadow stage traces the
  // light's shadow ray alone
  uint8_t* shadow_kinds;
  MirrorQuery* image;
  // Whitted: the vertex being lit and the depth-first stack, stack_size entries per state,
  // slot-major: entry k of state i at stack[k * width + i], so the states of a warp reading
  // their k-th entries read adjacent memory (coalesced on a GPU)
  WhittedVertex* vertex;
  WhittedTask* stack;
  uint32_t* top;
  uint32_t stack_size;
  uint32_t width;  // states in the batch
};

TRACER_HD PathState load_path(const StreamStates& st, uint32_t i) {
  PathState p;
  p.ray = {st.origin[i], st.dir[i]};
  p.radiance = st.radiance[i];
#define TRACER_PATH_LOAD(Type, Stored, name, initial) p.name = static_cast<Type>(st.name[i]);
  TRACER_PATH_STATE(TRACER_PATH_LOAD)
#undef TRACER_PATH_LOAD
  return p;
}

TRACER_HD void store_path(const StreamStates& st, uint32_t i, const PathState& p) {
  st.origin[i] = p.ray.origin;
  st.dir[i] = p.ray.dir;
  st.radiance[i] = p.radiance;
#define TRACER_PATH_STORE(Type, Stored, name, initial) st.name[i] = static_cast<Stored>(p.name);
  TRACER_PATH_STATE(TRACER_PATH_STORE)
#undef TRACER_PATH_STORE
}

TRACER_HD void store_shadow_ray(const StreamStates& st, uint32_t i, const Ray& ray, float tmax, uint32_t emitter) {
  st.shadow_origin[i] = ray.origin;
  st.shadow_dir[i] = ray.dir;
  st.shadow_tmax[i] = tmax;
  st.shadow_emitter[i] = emitter;
}

// The Whitted state's next task popped into its ray, or done when the stack is empty.
TRACER_HD uint8_t whitted_pop(const StreamStates& st, uint32_t i) {
  if (st.top[i] == 0u) return kStreamDone;
  const WhittedTask task = st.stack[static_cast<size_t>(--st.top[i]) * st.width + i];
  st.vertex[i].task = task;
  st.origin[i] = task.ray.origin;
  st.dir[i] = task.ray.dir;
  return kStreamTrace;
}

// A Whitted state from its hit (or resumed after a shadow ray) to its next ray or shadow ray.
TRACER_HD uint8_t whitted_shade(const SceneView& scene, const StreamStates& st, uint32_t i, RayCounts& counts) {
  WhittedVertex& v = st.vertex[i];
  if (!(st.next[i] & kStreamResume) && !whitted_begin(scene, v.task, st.hit[i], v, st.radiance[i]))
    return whitted_pop(st, i);
  Ray shadow;
  float tmax;
  if (whitted_next_light(scene, v, shadow, tmax, counts)) {
    store_shadow_ray(st, i, shadow, tmax, kNoHit);
    return kStreamShadow | kStreamResume;
  }
  int top = static_cast<int>(st.top[i]);
  whitted_finish(scene, v, st.radiance[i], st.stack + i, st.width, top, counts);
  st.top[i] = static_cast<uint32_t>(top);
  return whitted_pop(st, i);
}

TRACER_HD void stream_generate(const SceneView& scene, const StreamStates& st, uint32_t i, RayCounts& counts) {
  const uint32_t width = scene.settings.width;
  const Ray ray = sample_camera_ray(scene, st.pixel[i] % width, st.pixel[i] / width, st.sample[i], counts);
  st.radiance[i] = {0.0f, 0.0f, 0.0f};
  st.next[i] = kStreamTrace;
  switch (scene.settings.integrator) {
    case IntegratorKind::Path: store_path(st, i, path_start(ray)); break;
    case IntegratorKind::Whitted:
      st.top[i] = 0u;
      st.vertex[i].task = {ray, {1.0f, 1.0f, 1.0f}, 0u};
      st.origin[i] = ray.origin;
      st.dir[i] = ray.dir;
      break;
    default:
      st.origin[i] = ray.origin;
      st.dir[i] = ray.dir;
      break;
  }
}

// The shade stage by the integrator kKind (Normals: any debug view), as render_sample_as: a GPU
// kernel compiled for one integrator holds only its code (cuda/gpu_stream.cu).
template <IntegratorKind kKind, uint32_t kFeatures = TRACER_KERNEL_FEATURES>
TRACER_HD void stream_shade_as(const SceneView& scene, const StreamStates& st, uint32_t i, RayCounts& counts) {
  if constexpr (kKind == IntegratorKind::Path) {
    PathState p = load_path(st, i);
    ShadowQuery shadow;
    MirrorQuery image;
    const PathStep step = path_shade<kFeatures>(scene, st.pixel[i], st.sample[i], st.hit[i], p, shadow, image, counts);
    store_path(st, i, p);
    if (step.shadow) {
      store_shadow_ray(st, i, shadow.ray, shadow.tmax, shadow.emitter);
      st.shadow_contribution[i] = shadow.contribution;
    }
    if (st.shadow_kinds) {
      if (step.mirror) st.image[i] = image;
      st.shadow_kinds[i] = static_cast<uint8_t>((step.shadow ? unsigned{kShadowLight} : 0u) |
                                                (step.mirror ? unsigned{kShadowMirror} : 0u));
    }
    st.next[i] = static_cast<uint8_t>((step.shadow || step.mirror ? unsigned{kStreamShadow} : 0u) |
                                      (step.alive ? unsigned{kStreamTrace} : 0u));
  } else if constexpr (kKind == IntegratorKind::Whitted) {
    st.next[i] = whitted_shade(scene, st, i, counts);
  } else {
    st.radiance[i] = debug_view(scene, {st.origin[i], st.dir[i]}, st.hit[i]);
    st.next[i] = kStreamDone;
  }
}

TRACER_HD void stream_shade(const SceneView& scene, const StreamStates& st, uint32_t i, RayCounts& counts) {
  switch (scene.settings.integrator) {
    case IntegratorKind::Path: stream_shade_as<IntegratorKind::Path>(scene, st, i, counts); break;
    case IntegratorKind::Whitted: stream_shade_as<IntegratorKind::Whitted>(scene, st, i, counts); break;
    default: stream_shade_as<IntegratorKind::Normals>(scene, st, i, counts); break;
  }
}

// The closest-hit stage for state i, with the trace code kCode (kernel/accel/trace_code.h).
template <uint32_t kCode = kTraceAll>
TRACER_HD void stream_closest(const SceneView& scene, const StreamStates& st, uint32_t i) {
  st.hit[i] = trace_closest<kCode>(scene, {st.origin[i], st.dir[i]}, kInfinity);
}

// The shadow stage for state i, with the trace code kCode: a path adds the light sample's and
// then the mirror image's contribution, in the megakernel's order.
template <uint32_t kCode = kTraceAll>
TRACER_HD void stream_shadow(const SceneView& scene, const StreamStates& st, uint32_t i) {
  const uint8_t kinds = st.shadow_kinds ? st.shadow_kinds[i] : uint8_t{kShadowLight};
  ShadowQuery light;
  if (kinds & kShadowLight)
    light = {{st.shadow_origin[i], st.shadow_dir[i]}, st.shadow_tmax[i], st.shadow_emitter[i], {0.0f, 0.0f, 0.0f}};
  const uint8_t clear = trace_shadows<kCode>(scene, kinds, light, st.image, i);
  if (clear & kShadowLight) {
    if (scene.settings.integrator == IntegratorKind::Whitted)
      whitted_add_light(scene, st.vertex[i]);
    else
      st.radiance[i] += st.shadow_contribution[i];
  }
  if (clear & kShadowMirror) st.radiance[i] += st.image[i].to_mirror.contribution;
}

// One stage for state i: what the schedulers call per queue entry.
TRACER_HD void stream_stage(const SceneView& scene, StreamStage stage, const StreamStates& st, uint32_t i,
                            RayCounts& counts) {
  switch (stage) {
    case StreamStage::Generate: stream_generate(scene, st, i, counts); break;
    case StreamStage::Closest: stream_closest(scene, st, i); break;
    case StreamStage::Shade: stream_shade(scene, st, i, counts); break;
    case StreamStage::Shadow: stream_shadow(scene, st, i); break;
  }
}

// Item first + i of the target as state i. Items are pixel-major: item g is sample
// begin + g % samples of the (g / samples)-th pixel.
TRACER_HD void stream_begin_item(const StreamTarget& target, const StreamStates& st, uint64_t first, size_t i) {
  const uint32_t samples = target.end - target.begin;
  const uint64_t g = first + i;
  const size_t p = static_cast<size_t>(g / samples);
  st.pixel[i] = target.pixels ? target.pixels[p] : static_cast<uint32_t>(p);
  st.sample[i] = target.begin + static_cast<uint32_t>(g % samples);
}

// The batch's samples of its p-th pixel (counted over the target, as items are), in sample
// order, into the film (or the halves, or samples[]): what every backend's end_batch does per pixel.
TRACER_HD void stream_end_pixel(const StreamTarget& target, const StreamStates& st, uint64_t first, size_t count,
                                uint64_t p) {
  const uint64_t samples = target.end - target.begin;
  const uint64_t from = p * samples > first ? p * samples : first;
  const uint64_t to = (p + 1) * samples < first + count ? (p + 1) * samples : first + count;
  for (uint64_t g = from; g < to; ++g) {
    const size_t i = static_cast<size_t>(g - first);
    if (target.samples) {
      target.samples[g] = st.radiance[i];
      continue;
    }
    const uint32_t pixel = st.pixel[i];
    FilmSum& sum =
        target.film ? target.film[pixel] : (st.sample[i] % 2u == 0u ? target.even[pixel] : target.odd[pixel]);
    film_add(sum, st.radiance[i]);
  }
}

}  // namespace tracer
