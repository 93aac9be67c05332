// What a command printed must reach its reader: a table or a hash printed to a full disk
// (`tracer golden list > /full/file`) or to a closed descriptor was lost while the command
// exited 0. Each main ends through this check, as coreutils' close_stdout does.
#pragma once
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace tracer {

// `code` when every byte printed to stdout was written; else 2, after saying why on stderr.
inline int exit_code_after_flushing_stdout(int code) {
  errno = 0;
  const bool flush_failed = std::fflush(stdout) != 0;
  const int flush_errno = errno;
  if (!flush_failed && !std::ferror(stdout)) return code;
  std::fprintf(stderr, "error: standard output: cannot write: %s\n",
               flush_errno != 0 ? std::strerror(flush_errno) : "an earlier write failed");
  return 2;
}

}  // namespace tracer
