// The stream schedule's OpenMP loop (kernel/integrator/stream.h): batches of pixel samples
// as ray states, each stage run over its queue by all threads, the queues compacted between
// stages, and each batch's samples added to the film in pixel-sample order. The image equals
// the megakernel's (render_cpu.h) bit for bit.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>

#include "kernel/base/film.h"
#include "kernel/integrator/ray_counts.h"
#include "kernel/scene/scene_view.h"
#include "render/cpu_kernel.h"

namespace tracer {

// What a stream render measured: queue sizes and the memory of its ray states.
struct StreamStats {
  uint64_t batches = 0;
  uint64_t waves = 0;          // rounds of closest-hit, shade and shadow stages
  uint64_t largest_queue = 0;  // states in the largest closest-hit queue
  uint64_t shadow_rays = 0;    // entries of all shadow queues
  size_t bytes_per_state = 0;  // the ray-state arrays' bytes per sample in flight
  size_t state_bytes = 0;      // all of them, for the stream width
};

// Where a stream render's samples go: samples [begin, end) of pixels[0..count) (indices
// y * width + x; every pixel in order when `pixels` is null, count = width * height), added
// to film[pixel], or by sample parity to even[pixel] and odd[pixel] (adaptive sampling).
struct StreamTarget {
  const uint32_t* pixels;
  size_t count;
  uint32_t begin, end;
  FilmSum* film;
  FilmSum* even;
  FilmSum* odd;
};

// Renders `target` with at most view.settings.stream_width samples in flight (an InputError
// naming --stream-width when its states cannot be allocated). `progress` (optional) gets the
// samples done and the total after each batch.
void render_stream(const SceneView& view, const CpuKernelVariant& variant, const StreamTarget& target, int threads,
                   RayCounts& counts, StreamStats& stats,
                   const std::function<void(uint64_t done, uint64_t total)>& progress = {});

}  // namespace tracer
