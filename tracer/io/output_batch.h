// The outputs of one command, written all or nothing. Each file is written to a temporary
// beside its target (same directory, a random name created exclusively, never through a
// symlink), flushed to disk and closed; only when
// every file of the batch got that far are they renamed over their targets. An error, or
// SIGINT, SIGTERM or SIGHUP while a batch is open, removes the temporaries, so a failed or
// interrupted command leaves every earlier file exactly as it was and no temporary behind;
// those signals arriving during the renames wait until the last one is done.
//
// SIGKILL cannot wait. Files that must agree after one (a golden image and the manifest
// that records its hash) are committed through a journal: a file in their one directory,
// itself renamed into place, that lists each temporary and its target. Its rename is the
// commit point: before it nothing changed; after it finish_interrupted_commit renames what
// is left, so the next command to look finds all the new files or all the old ones.
#pragma once
#include <functional>
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

  // commit() through JOURNAL, which must sit in the directory of every target. on_step, for
  // tests that kill the command part way, is called after the journal lands (0), after
  // each rename (1..n) and after the journal is removed (n + 1).
  void commit(const std::string& journal, const std::function<void(size_t step)>& on_step = {});

 private:
  std::vector<std::pair<std::string, std::string>> files_;  // (temporary, target)
};

// One file written all or nothing: add and commit.
void write_file_atomically(const std::string& path, const std::string& bytes);

// After a SIGKILL: renames the temporaries JOURNAL lists over their targets and removes it.
// Returns false when there is no journal; InputError naming the line when it is malformed.
bool finish_interrupted_commit(const std::string& journal);

// Removes the temporaries of batches killed before their commit point from DIR and returns
// how many. Only for a directory whose writers all hold a lock the caller holds now.
size_t remove_orphan_temporaries(const std::string& dir);

}  // namespace tracer
