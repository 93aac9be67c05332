// Whole-file reads of text and binary files: anything but a regular file is refused (a FIFO
// or a device would block or never end). Writes: io/output_batch.h.
#pragma once
#include <cstdint>
#include <string>

namespace tracer {

// InputError "PATH: cannot open WHAT" (or: is not a regular file, is larger than max_bytes).
std::string read_text_file(const std::string& path, const std::string& what, uint64_t max_bytes = UINT64_MAX);

}  // namespace tracer
