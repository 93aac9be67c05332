#include "golden/golden_update.h"

#include <filesystem>
#include <regex>

#include "golden/golden_check.h"
#include "golden/golden_lock.h"
#include "golden/golden_manifest.h"
#include "image/image_io.h"
#include "image/pixel_hash.h"
#include "io/input_error.h"
#include "io/shell.h"

namespace fs = std::filesystem;

namespace tracer {
namespace {

// The old reference image, or nothing when it is missing or unreadable.
std::optional<Image> read_old_image(const std::string& path) {
  try {
    if (!fs::exists(path)) return std::nullopt;
    return read_image(path);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace

const char* change_name(GoldenChangeKind kind) {
  switch (kind) {
    case GoldenChangeKind::New: return "new";
    case GoldenChangeKind::Changed: return "changed";
    case GoldenChangeKind::Repaired: return "repaired";
    case GoldenChangeKind::Unchanged: return "unchanged";
  }
  return "?";
}

std::vector<std::string> uncommitted_golden_edits(const std::string& root) {
  std::string output;
  const int code =
      run_capture("git -C " + shell_quote(root) + " status --porcelain --untracked-files=all -- golden 2>&1", output);
  if (code != 0)
    throw InputError(root + ": cannot tell whether golden/ has uncommitted edits (git status failed: " +
                     output.substr(0, output.find('\n')) + "); pass --force to update anyway");
  std::vector<std::string> edits;
  size_t start = 0;
  while (start < output.size()) {
    const size_t end = output.find('\n', start);
    const std::string line = output.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!line.empty()) edits.push_back(line);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return edits;
}

std::vector<GoldenChange> update_goldens(const UpdateRequest& request) {
  const GoldenLock lock(request.root, GoldenAccess::Write);
  if (!request.force) {
    const std::vector<std::string> edits = uncommitted_golden_edits(request.root);
    if (!edits.empty()) {
      std::string list;
      for (const std::string& e : edits) list += "\n  " + e;
      throw InputError((fs::path(request.root) / "golden").string() +
                       ": has uncommitted edits; commit or revert them first, or pass --force:" + list);
    }
  }
  // std::regex compiles and matches by recursion: a pattern of thousands of nested groups ran out
  // of stack. 256 characters hold any name of the manifest (at most 100) and any useful pattern.
  if (request.filter.size() > 256)
    throw InputError("--filter: " + std::to_string(request.filter.size()) +
                     " characters; at most 256 (golden names have at most 100)");
  std::regex filter;
  try {
    filter = std::regex(request.filter.empty() ? std::string(".*") : request.filter, std::regex::ECMAScript);
  } catch (const std::regex_error& e) {
    throw InputError("--filter " + request.filter + ": not a valid regular expression (" + e.what() + ")");
  }
  GoldenManifest manifest = read_manifest(request.root);

  // Render everything first; write nothing until every matching golden rendered cleanly.
  struct Pending {
    GoldenEntry* entry;
    GoldenRender render;
    GoldenChange change;
  };
  std::vector<Pending> pending;
  for (GoldenEntry& entry : manifest.entries) {
    if (!std::regex_search(entry.name, filter)) continue;
    Pending p{&entry, render_golden(manifest, entry, request.threads), {}};
    if (p.render.nonfinite_samples > 0)
      throw InputError(entry.name + ": the new image has " + std::to_string(p.render.nonfinite_samples) +
                       " NaN/inf samples; a golden must be finite");
    if (p.render.overflow_samples > 0)
      throw InputError(entry.name + ": the new image has " + std::to_string(p.render.overflow_samples) +
                       " samples beyond the film's range (2^30); a golden must not overflow");
    p.change.name = entry.name;
    const std::optional<Image> old = read_old_image(manifest.image_path(entry));
    if (entry.hash.empty())
      p.change.kind = GoldenChangeKind::New;
    else if (p.render.hash != entry.hash)
      p.change.kind = GoldenChangeKind::Changed;
    else if (!old || pixel_hash(*old) != entry.hash)
      p.change.kind = GoldenChangeKind::Repaired;
    if (old && p.change.kind != GoldenChangeKind::Unchanged) {
      CompareOptions exact;
      exact.fail = exact.warn = 0.0f;
      p.change.metrics = compare_images(p.render.image, *old, exact);
    }
    pending.push_back(std::move(p));
  }
  if (pending.empty()) throw InputError(manifest.path + ": no golden name matches --filter \"" + request.filter + "\"");

  // The new images and the manifest land together or not at all.
  OutputBatch outputs;
  bool manifest_changed = false;
  std::vector<GoldenChange> changes;
  for (Pending& p : pending) {
    if (p.change.kind != GoldenChangeKind::Unchanged) {
      add_image(outputs, p.render.image, manifest.image_path(*p.entry));
      p.entry->hash = p.render.hash;
      p.entry->options = p.render.options;
      manifest_changed = true;
    }
    changes.push_back(p.change);
  }
  if (manifest_changed) add_manifest(outputs, manifest);
  outputs.commit(golden_journal_path(request.root));
  return changes;
}

}  // namespace tracer
