// The outputs of one command, written all or nothing. Each file is written to a temporary
// beside its target (same directory, a random name created exclusively, never through a
// symlink), flushed to disk and closed; only when
// every file of the batch got that far are they renamed over their targets. An error, or
// SIGINT, SIGTERM or SIGHUP while a batch is open, removes the temporaries, so a failed or
// interrupted command leaves every earlier file exactly as it was and no temporary behind.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace tracer {

class OutputBatch {
 public:
  OutputBatch() = default;
  OutputBatch(const OutputBatch&) = delete;
  OutputBatch& operator=(const OutputBatch&) = delete;
  ~OutputBatch();  // removes the temporaries of a batch never committed

  // Writes `bytes` to target's temporary, checking every write, fsync and close; InputError
  // naming target when one fails.
  void add(const std::string& target, const std::string& bytes);

  void commit();  // renames every temporary over its target, in the order added

 private:
  std::vector<std::pair<std::string, std::string>> files_;  // (temporary, target)
};

// One file written all or nothing: add and commit.
void write_file_atomically(const std::string& path, const std::string& bytes);

}  // namespace tracer
