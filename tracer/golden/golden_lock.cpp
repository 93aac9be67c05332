#include "golden/golden_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "io/input_error.h"
#include "io/output_batch.h"

namespace fs = std::filesystem;

namespace tracer {
namespace {

std::string golden_dir(const std::string& root) { return (fs::path(root) / "golden").string(); }

// flock, saying once on stderr why the command waits when another holds the lock.
void lock_waiting(int fd, int operation, const std::string& dir) {
  if (::flock(fd, operation | LOCK_NB) == 0) return;
  if (errno != EWOULDBLOCK) throw InputError(dir + ": cannot lock: " + std::strerror(errno));
  std::fprintf(stderr, "%s: waiting for another golden command using this directory to finish (%s)\n", dir.c_str(),
               operation == LOCK_EX ? "updates wait for checks and updates" : "checks wait for updates");
  while (::flock(fd, operation) != 0)
    if (errno != EINTR) throw InputError(dir + ": cannot lock: " + std::strerror(errno));
}

// Leftovers of a killed update: its journal, or its temporaries.
bool has_leftovers(const std::string& dir, const std::string& journal) {
  std::error_code ec;
  if (fs::exists(fs::symlink_status(journal, ec))) return true;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.path().filename().string().rfind(".tracer-", 0) == 0) return true;
  return false;
}

}  // namespace

std::string golden_journal_path(const std::string& root) {
  return (fs::path(golden_dir(root)) / ".tracer-commit-journal").string();
}

GoldenLock::GoldenLock(const std::string& root, GoldenAccess access) {
  const std::string dir = golden_dir(root);
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw InputError(dir + ": cannot open the golden directory: " + std::strerror(errno));
  const std::string journal = golden_journal_path(root);
  try {
    lock_waiting(fd_, access == GoldenAccess::Write ? LOCK_EX : LOCK_SH, dir);
    if (!has_leftovers(dir, journal)) return;
    if (access == GoldenAccess::Read) lock_waiting(fd_, LOCK_EX, dir);  // to repair: not atomic, so look again
    if (finish_interrupted_commit(journal))
      std::fprintf(stderr, "%s: finished the commit of a golden update that was killed (%s)\n", dir.c_str(),
                   journal.c_str());
    if (const size_t removed = remove_orphan_temporaries(dir))
      std::fprintf(stderr, "%s: removed %zu temporaries of a golden update killed before it wrote anything\n",
                   dir.c_str(), removed);
    if (access == GoldenAccess::Read) lock_waiting(fd_, LOCK_SH, dir);
  } catch (...) {
    ::close(fd_);
    throw;
  }
}

GoldenLock::~GoldenLock() { ::close(fd_); }  // closing the last descriptor releases the flock

}  // namespace tracer
