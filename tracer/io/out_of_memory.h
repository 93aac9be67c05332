// An allocation that fails while a command works on one file is that file's error: an
// InputError (exit 2) naming the file and what the command was doing, never a bare
// std::bad_alloc. The parallel regions (render, BVH builds) allocate nothing, so none can
// end in std::terminate; their buffers are allocated before them, inside these guards.
#pragma once
#include <new>
#include <string>

#include "io/input_error.h"

namespace tracer {

template <class Work>
auto naming_file_when_out_of_memory(const std::string& file, const std::string& doing, Work&& work)
    -> decltype(work()) {
  try {
    return work();
  } catch (const std::bad_alloc&) {
    throw InputError(file + ": out of memory while " + doing + "; this machine cannot hold it");
  }
}

}  // namespace tracer
