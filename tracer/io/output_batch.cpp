#include "io/output_batch.h"

#include <fcntl.h>
#include <limits.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <random>

#include "io/input_error.h"

namespace tracer {
namespace {

std::string errno_text() { return std::strerror(errno); }

// Temporaries a signal handler removes: fixed storage, since a handler may only call
// async-signal-safe functions (unlink, raise). A slot is published by its flag after its path.
constexpr int kSlots = 32;
char pending_paths[kSlots][PATH_MAX];
std::atomic<bool> pending_used[kSlots];

void remove_pending_and_reraise(int sig) {
  for (int i = 0; i < kSlots; ++i)
    if (pending_used[i].load()) ::unlink(pending_paths[i]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void install_signal_cleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction old {};
      if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_DFL)
        std::signal(sig, remove_pending_and_reraise);
    }
  });
}

void track(const std::string& temp) {
  install_signal_cleanup();
  if (temp.size() >= PATH_MAX) return;  // still removed on errors, not on signals
  static std::mutex lock;
  const std::lock_guard<std::mutex> hold(lock);
  for (int i = 0; i < kSlots; ++i)
    if (!pending_used[i].load()) {
      std::memcpy(pending_paths[i], temp.c_str(), temp.size() + 1);
      pending_used[i].store(true);
      return;
    }
}

void untrack(const std::string& temp) {
  for (int i = 0; i < kSlots; ++i)
    if (pending_used[i].load() && temp == pending_paths[i]) pending_used[i].store(false);
}

// A new temporary beside target, created exclusively (O_CREAT | O_EXCL, which also refuses a
// symlink planted at the name) under a random name of fixed length, so that nobody can guess
// it in advance and a target name of the longest legal length still has one. Returns the fd.
int create_temporary_for(const std::string& target, std::string& temp) {
  static const char kAlphabet[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  static std::mutex lock;
  static std::random_device device;
  const std::filesystem::path parent = std::filesystem::path(target).parent_path();
  for (int attempt = 0; attempt < 64; ++attempt) {
    std::string name = ".tracer-";
    {
      const std::lock_guard<std::mutex> hold(lock);
      for (int i = 0; i < 16; ++i) name += kAlphabet[device() % (sizeof kAlphabet - 1)];
    }
    temp = (parent / (name + ".tmp")).string();
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

}  // namespace

OutputBatch::~OutputBatch() {
  for (const auto& [temp, target] : files_) {
    ::unlink(temp.c_str());
    untrack(temp);
  }
}

void OutputBatch::add(const std::string& target, const std::string& bytes) {
  for (const auto& [temp, earlier] : files_)
    if (earlier == target) throw InputError(target + ": named twice as an output");
  // A directory would fail only at the rename, after other outputs landed; a device or FIFO
  // would be replaced by a regular file when the tracer runs as root (/dev/null was).
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::symlink_status(target, ec);
  if (std::filesystem::is_directory(status)) throw InputError(target + ": cannot write: it is a directory");
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
      !std::filesystem::is_symlink(status))
    throw InputError(target + ": cannot write: it is a device, FIFO or socket, not a file");
  std::string temp;
  const int fd = create_temporary_for(target, temp);
  if (fd < 0) throw InputError(target + ": cannot write: " + errno_text());
  track(temp);
  files_.emplace_back(temp, target);  // from here the destructor removes it
  std::string failure;
  for (size_t done = 0; failure.empty() && done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      failure = n < 0 ? errno_text() : "no space written";
    else
      done += static_cast<size_t>(n);
  }
  if (failure.empty() && ::fsync(fd) != 0) failure = errno_text();
  if (::close(fd) != 0 && failure.empty()) failure = errno_text();
  if (!failure.empty()) throw InputError(target + ": cannot write: " + failure);
}

void OutputBatch::commit() {
  for (size_t i = 0; i < files_.size(); ++i) {
    const auto& [temp, target] = files_[i];
    if (std::rename(temp.c_str(), target.c_str()) != 0) {
      const std::string failure = errno_text();
      throw InputError(target + ": cannot write: " + failure +
                       (i > 0 ? " (" + files_[0].second + " and the outputs before this one were written)" : ""));
    }
    untrack(temp);
  }
  files_.clear();
}

void write_file_atomically(const std::string& path, const std::string& bytes) {
  OutputBatch batch;
  batch.add(path, bytes);
  batch.commit();
}

}  // namespace tracer
