#include "io/output_batch.h"

#include <fcntl.h>
#include <limits.h>
#include <unistd.h>

#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <random>

#include "io/input_error.h"
#include "io/text_file.h"

namespace tracer {
namespace {

std::string errno_text() { return std::strerror(errno); }

// Temporaries a signal handler removes: fixed storage, since a handler may only call
// async-signal-safe functions (unlink, raise). A slot is published by its flag after its path.
constexpr int kSlots = 32;
char pending_paths[kSlots][PATH_MAX];
std::atomic<bool> pending_used[kSlots];

// While a batch renames its files, SIGINT, SIGTERM and SIGHUP wait: the handler notes the
// signal, and the commit raises it once the last rename is done.
std::atomic<int> commits_running{0};
std::atomic<int> deferred_signal{0};

void remove_pending_and_reraise(int sig) {
  if (commits_running.load() > 0) {
    deferred_signal.store(sig);
    return;
  }
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

class SignalsWait {
 public:
  SignalsWait() { commits_running.fetch_add(1); }
  SignalsWait(const SignalsWait&) = delete;
  SignalsWait& operator=(const SignalsWait&) = delete;
  ~SignalsWait() {
    if (commits_running.fetch_sub(1) == 1)
      if (const int sig = deferred_signal.exchange(0)) remove_pending_and_reraise(sig);
  }
};

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

constexpr const char* kTemporaryPrefix = ".tracer-";
constexpr size_t kTemporaryRandomLength = 16;
constexpr const char* kJournalFormat = "tracer-commit-journal/1";

bool is_temporary_name(const std::string& name) {
  const std::string prefix = kTemporaryPrefix;
  if (name.size() != prefix.size() + kTemporaryRandomLength + 4 || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - 4, 4, ".tmp") != 0)
    return false;
  for (size_t i = prefix.size(); i < prefix.size() + kTemporaryRandomLength; ++i)
    if (!std::islower(static_cast<unsigned char>(name[i])) && !std::isdigit(static_cast<unsigned char>(name[i])))
      return false;
  return true;
}

// Every byte written, then fsync and close, each checked; the error text, or empty.
std::string write_all_and_close(int fd, const std::string& bytes) {
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
  return failure;
}

// A rename is durable once its directory is flushed.
void sync_directory(const std::filesystem::path& dir, const std::string& who) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  const bool ok = fd >= 0 && ::fsync(fd) == 0;
  const std::string failure = ok ? "" : errno_text();
  if (fd >= 0) ::close(fd);
  if (!ok) throw InputError(who + ": cannot flush its directory: " + failure);
}

std::filesystem::path directory_of(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  std::error_code ec;
  return std::filesystem::weakly_canonical(std::filesystem::absolute(parent.empty() ? "." : parent), ec);
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
    std::string name = kTemporaryPrefix;
    {
      const std::lock_guard<std::mutex> hold(lock);
      for (size_t i = 0; i < kTemporaryRandomLength; ++i) name += kAlphabet[device() % (sizeof kAlphabet - 1)];
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
  const std::string failure = write_all_and_close(fd, bytes);
  if (!failure.empty()) throw InputError(target + ": cannot write: " + failure);
}

void OutputBatch::commit() {
  const SignalsWait wait;
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

void OutputBatch::commit(const std::string& journal, const std::function<void(size_t)>& on_step) {
  const std::filesystem::path dir = directory_of(journal);
  std::string text = std::string(kJournalFormat) + "\n";
  for (const auto& [temp, target] : files_) {
    if (directory_of(target) != dir)
      throw InputError(target + ": cannot write: not in the directory of the commit journal " + journal);
    const std::string name = std::filesystem::path(target).filename().string();
    if (name.find_first_of("\t\n") != std::string::npos)
      throw InputError(target + ": cannot write: a tab or newline in the name cannot be journaled");
    text += std::filesystem::path(temp).filename().string() + "\t" + name + "\n";
  }
  const SignalsWait wait;
  std::string journal_temp;
  const int fd = create_temporary_for(journal, journal_temp);
  if (fd < 0) throw InputError(journal + ": cannot write: " + errno_text());
  std::string failure = write_all_and_close(fd, text);
  if (failure.empty() && std::rename(journal_temp.c_str(), journal.c_str()) != 0) failure = errno_text();
  if (!failure.empty()) {
    ::unlink(journal_temp.c_str());
    throw InputError(journal + ": cannot write: " + failure);
  }
  // The commit point: from here the journal owns the temporaries, and a failed rename leaves
  // them for finish_interrupted_commit.
  std::vector<std::pair<std::string, std::string>> files = std::move(files_);
  files_.clear();
  for (const auto& file : files) untrack(file.first);
  sync_directory(dir, journal);
  if (on_step) on_step(0);
  for (size_t i = 0; i < files.size(); ++i) {
    if (std::rename(files[i].first.c_str(), files[i].second.c_str()) != 0)
      throw InputError(files[i].second + ": cannot write: " + errno_text() + "; the next command to read " + journal +
                       " finishes the commit");
    if (on_step) on_step(i + 1);
  }
  sync_directory(dir, journal);
  if (::unlink(journal.c_str()) != 0)
    throw InputError(journal + ": cannot remove the finished journal: " + errno_text());
  sync_directory(dir, journal);
  if (on_step) on_step(files.size() + 1);
}

void write_file_atomically(const std::string& path, const std::string& bytes) {
  OutputBatch batch;
  batch.add(path, bytes);
  batch.commit();
}

bool finish_interrupted_commit(const std::string& journal) {
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(journal, ec))) return false;
  const SignalsWait wait;
  const std::string text = read_text_file(journal, "commit journal", 1u << 20);
  const std::filesystem::path dir = std::filesystem::path(journal).parent_path();
  std::vector<std::pair<std::string, std::string>> renames;
  size_t line_number = 0;
  size_t start = 0;
  while (start < text.size()) {
    const size_t end = text.find('\n', start);
    if (end == std::string::npos)
      throw InputError(journal + ": line " + std::to_string(line_number + 1) + ": cut short");
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    if (++line_number == 1) {
      if (line != kJournalFormat) throw InputError(journal + ": line 1: expected " + kJournalFormat);
      continue;
    }
    const size_t tab = line.find('\t');
    const std::string temp = line.substr(0, tab);
    const std::string target = tab == std::string::npos ? "" : line.substr(tab + 1);
    if (!is_temporary_name(temp) || target.empty() || target == "." || target == ".." ||
        target.find_first_of("/\t") != std::string::npos)
      throw InputError(journal + ": line " + std::to_string(line_number) +
                       ": expected a tracer temporary, a tab and a file name in the journal's directory");
    renames.emplace_back((dir / temp).string(), (dir / target).string());
  }
  if (line_number == 0) throw InputError(journal + ": empty; expected " + kJournalFormat);
  for (const auto& [temp, target] : renames) {
    const std::filesystem::file_status status = std::filesystem::symlink_status(temp, ec);
    if (!std::filesystem::exists(status)) continue;  // renamed before the command was killed
    if (!std::filesystem::is_regular_file(status))
      throw InputError(journal + ": " + temp + " is not a regular file; the journal was not written by the tracer");
    if (std::rename(temp.c_str(), target.c_str()) != 0)
      throw InputError(target + ": cannot finish the commit of " + journal + ": " + errno_text());
  }
  sync_directory(dir, journal);
  if (::unlink(journal.c_str()) != 0)
    throw InputError(journal + ": cannot remove the finished journal: " + errno_text());
  sync_directory(dir, journal);
  return true;
}

size_t remove_orphan_temporaries(const std::string& dir) {
  size_t removed = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (is_temporary_name(name) && entry.is_regular_file(ec) && !entry.is_symlink(ec))
      removed += ::unlink(entry.path().c_str()) == 0;
  }
  return removed;
}

}  // namespace tracer
