// The stream schedule's stages and a ray state's next step (kernel/integrator/stream.h), apart
// from the stages themselves so that the host loop (render/stream_schedule.h) names them
// without compiling the integrators.
#pragma once
#include <cstdint>

namespace tracer {

enum class StreamStage : uint32_t {
  Generate,  // the camera ray of (pixel[i], sample[i]); next = trace
  Closest,   // hit[i]: the closest hit of the state's ray
  Shade,     // the integrator's step at hit[i] (or a resumed Whitted vertex): sets next[i]
  Shadow,    // the shadow ray's visibility; its contribution added if the light is visible
};

// What a state does next (bits of next[i]): trace its ray, trace its shadow ray, shade again
// without a new hit (a Whitted vertex with lights left). 0: the sample is done.
enum StreamNext : uint8_t { kStreamDone = 0u, kStreamTrace = 1u, kStreamShadow = 2u, kStreamResume = 4u };

}  // namespace tracer
