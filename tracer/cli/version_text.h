// What `tracer --version` prints: the version, the commit it was built from, the compiler,
// the CPU kernel variants compiled in (and the instruction set this CPU runs) and whether
// the CUDA renderer was built.
#pragma once
#include <string>

namespace tracer {

std::string version_text();

}  // namespace tracer
