// The stream schedule's OpenMP loop (kernel/integrator/stream.h): batches of pixel samples
// as ray states, each stage run over its queue by all threads, the queues compacted between
// stages, and each batch's samples added to the film in pixel-sample order. The image equals
// the megakernel's (render_cpu.h) bit for bit.
#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>

#include "kernel/integrator/ray_counts.h"
#include "kernel/scene/scene_view.h"
#include "render/cpu_kernel.h"
#include "render/stream_schedule.h"

namespace tracer {

// Renders `target` with at most view.settings.stream_width samples in flight (an InputError
// naming --stream-width when its states cannot be allocated). `progress` (optional) gets the
// samples done and the total after each batch.
void render_stream(const SceneView& view, const CpuKernelVariant& variant, const StreamTarget& target, int threads,
                   RayCounts& counts, StreamStats& stats,
                   const std::function<void(uint64_t done, uint64_t total)>& progress = {});

}  // namespace tracer
