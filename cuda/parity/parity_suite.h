// The CPU/GPU parity cases as files of a GPU pack: each case names a kernel entry point of
// parity_cases.h, the generator of its inputs (parity_inputs.h: a seed and a count) and,
// for traversal and whole samples, the scene bundle it runs on. `tracer gpu-pack` computes
// the CPU's answers and stores their SHA-1; the runner recomputes the inputs (checking
// their SHA-1 too), evaluates them on the GPU or the CPU and compares the hashes.
#pragma once
#include <string>

#include "bundle/scene_bundle.h"
#include "parity_cases.h"

namespace tracer::parity {

enum class ParityKind : uint32_t { Math, Philox, Shapes, Trace, Sample, Lbvh, Adaptive, Stream, Bsdf };

struct ParitySpec {
  ParityKind kind;
  uint32_t function;  // Math: the MathFunction
  uint64_t seed;
  uint32_t count;  // Math: random pairs (and half as many domain points); Philox: queries;
                   // Shapes: spheres and triangles each; Trace: rays; Sample: unused;
                   // Lbvh: triangles, built into nodes and leaf order; Adaptive: pixels;
                   // Stream: the stream width; Bsdf: material queries
  uint32_t reserved;
  Vec3 lo, hi;  // Trace: the box the ray origins are drawn from
};

struct ParityCase {
  std::string name;
  ParitySpec spec{};
  SceneBundle scene;  // Trace, Sample and Stream
};

struct ParityAnswers {
  size_t inputs = 0;
  std::string inputs_sha1, answers_sha1;
  std::string answers;  // the answers' bytes, element after element
  uint32_t answer_size = 0;
  double seconds = 0;  // the evaluation's wall time on its device, transfers included
  std::string note;    // Lbvh on the GPU: the device build time
};

// The case's inputs, evaluated on the GPU (DeviceUnavailable without one) or on the CPU.
// Stream: every sample's radiance from the stream schedule's stages, on either device.
ParityAnswers evaluate_parity_case(const ParityCase& c, bool on_gpu, unsigned threads);

// The answers a case is checked against: evaluate_parity_case's on the CPU, except for a
// Stream case, whose reference is the megakernel's render_sample for every sample.
ParityAnswers reference_parity_answers(const ParityCase& c, unsigned threads);

// Index and description of answers that differ, at most `limit` of them.
std::string describe_differences(const ParityAnswers& expected, const ParityAnswers& got, size_t limit);

// A "parity" BundleFile: the case, its scene's sections, the CPU's inputs and answers hashes.
BundleFile encode_parity_case(const ParityCase& c, const ParityAnswers& cpu);
struct StoredParityCase {
  ParityCase parity;
  std::string inputs_sha1, answers_sha1;
};
StoredParityCase read_parity_case(const std::string& path);  // InputError naming the file

}  // namespace tracer::parity
