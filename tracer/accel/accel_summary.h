// What `tracer info` and `--stats` report of a built structure: its name as --accel spells
// it, its nodes (bvh, lbvh, kd-trees) and its cells (grid). Kept apart from the builders so
// that the scene (and CUDA code, C++17) can hold one without the builders' interface.
#pragma once
#include <cstddef>
#include <string>

namespace tracer {

struct AccelSummary {
  std::string name;
  size_t nodes = 0, cells = 0;
};

}  // namespace tracer
