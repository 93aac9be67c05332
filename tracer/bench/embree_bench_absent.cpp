// The Embree adapter's interface in a build without libembree-dev.
#include "bench/embree_bench.h"
#include "io/input_error.h"

namespace tracer {

bool embree_available() { return false; }

EmbreeRow embree_bench(const Scene&, const std::vector<Ray>&, const std::vector<Ray>&, const std::vector<Ray>&,
                       const std::vector<float>&, const std::vector<Hit>&, const std::vector<Hit>&, int, uint32_t,
                       const std::function<double()>&) {
  throw InputError("this build has no Embree adapter (install libembree-dev and reconfigure)");
}

}  // namespace tracer
