// Prints, per deterministic math function, the SHA-1 of its answers over the GPU pack's math
// parity inputs (edge pairs, random bit patterns with signaling NaNs among them, domain
// points). Built twice, optimized and at -O0; test `math.unoptimized` compares the two.
// At -O0 GCC executes every float/double conversion the source writes, and x86's, like
// PTX's cvt, turns a signaling NaN quiet; optimized, GCC folds a round trip away. So an
// answer that depends on that folding differs here as it differs on the GPU (docs/cuda.md).
#include <cstdio>

#include "io/sha1.h"
#include "parity_inputs.h"

namespace {
// A loop over arrays, as the parity runner evaluates them: GCC folds the round trip here and
// not where one call's answer is hashed at once.
__attribute__((noinline)) void evaluate(tracer::parity::MathFunction f, const tracer::parity::MathInputs& in,
                                        std::vector<float>& out) {
  for (size_t i = 0; i < in.a.size(); ++i) out[i] = tracer::parity::eval_math(f, in.a[i], in.b[i]);
}
}  // namespace

int main() {
  using namespace tracer;
  using namespace tracer::parity;
  const char* names[kMathFunctionCount] = {"sin", "cos", "tan", "asin", "acos", "atan2", "exp", "log", "pow"};
  for (uint32_t fi = 0; fi < kMathFunctionCount; ++fi) {
    const MathFunction f = static_cast<MathFunction>(fi);
    const MathInputs in = math_inputs(f, 0x6d617468ull + fi, 1u << 18, 1u << 16);
    std::vector<float> answers(in.a.size());
    evaluate(f, in, answers);
    Sha1 sha;
    sha.append(answers.data(), answers.size() * sizeof(float));
    std::printf("%-6s %s\n", names[fi], sha.hex_digest().c_str());
  }
  return 0;
}
