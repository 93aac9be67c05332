// One golden root, one writer: `golden update` holds ROOT/golden exclusively from before it
// reads the manifest until its images and manifest are committed, so two updates serialize
// instead of one losing the other's entries; `golden check` and `list` hold it shared
// while they read. The lock is flock(2) on the directory itself (no lock file to leave
// behind), released by the kernel when the process dies. Whoever takes it first finishes an
// update a SIGKILL interrupted (io/output_batch.h: the commit journal) and removes the
// temporaries of one killed before its commit point. A command that must wait says so.
#pragma once
#include <string>

namespace tracer {

enum class GoldenAccess { Read, Write };

class GoldenLock {
 public:
  GoldenLock(const std::string& root, GoldenAccess access);  // InputError when ROOT/golden cannot be opened
  GoldenLock(const GoldenLock&) = delete;
  GoldenLock& operator=(const GoldenLock&) = delete;
  ~GoldenLock();

 private:
  int fd_ = -1;
};

// ROOT/golden/.tracer-commit-journal: where golden update journals its commit.
std::string golden_journal_path(const std::string& root);

}  // namespace tracer
