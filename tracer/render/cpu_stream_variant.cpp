// The stream schedule's stages (kernel/integrator/stream.h) of one CPU kernel variant: compiled
// with cpu_kernel_variant.cpp's definitions and flags, in a file of their own so that GCC
// inlines the megakernel as it did before the stream schedule shared its steps.
#include "render/cpu_variant_prelude.h"

namespace TRACER_VARIANT {
#include "kernel/integrator/stream.h"
}  // namespace TRACER_VARIANT

#include "render/cpu_variant_bytes.h"

namespace TRACER_VARIANT {

void stream_stage(const ::tracer::SceneView& view, uint32_t stage, const void* states, const uint32_t* queue,
                  size_t begin, size_t end, ::tracer::RayCounts& counts) {
  const k::SceneView v = view_of(view);
  const k::StreamStates st = load<k::StreamStates>(states, 0);
  k::RayCounts c = load<k::RayCounts>(&counts, 0);
  for (size_t q = begin; q < end; ++q) k::stream_stage(v, static_cast<k::StreamStage>(stage), st, queue[q], c);
  store(&counts, 0, c);
}

}  // namespace TRACER_VARIANT
