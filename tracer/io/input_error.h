// The one error type for bad user input: the message names the file and the key path.
// The CLI prints it and exits with code 2 before any output file is created.
#pragma once
#include <stdexcept>
#include <string>

namespace tracer {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace tracer
