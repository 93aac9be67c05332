// Whole-file I/O for text and binary files. Reads refuse anything but a regular file (a
// FIFO or a device would block or never end). Writes go to a temporary file beside PATH
// that is renamed into place once every write, fsync and close has succeeded, so a failed
// or interrupted write never leaves a partial file or clobbers the old one.
#pragma once
#include <cstdint>
#include <string>

namespace tracer {

// InputError "PATH: cannot open WHAT" (or: is not a regular file, is larger than max_bytes).
std::string read_text_file(const std::string& path, const std::string& what, uint64_t max_bytes = UINT64_MAX);
void write_text_atomically(const std::string& path, const std::string& text);  // InputError when it cannot write

}  // namespace tracer
