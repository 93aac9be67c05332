// Whole-file text I/O. Writes go to PATH.tmp and are renamed into place, so an
// interrupted write never leaves a partial file or clobbers the old one.
#pragma once
#include <string>

namespace tracer {

std::string read_text_file(const std::string& path, const std::string& what);  // InputError: "PATH: cannot open WHAT"
void write_text_atomically(const std::string& path, const std::string& text);    // InputError when it cannot write

}  // namespace tracer
