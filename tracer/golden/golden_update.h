// `tracer golden update`: re-renders the goldens whose names match a filter and rewrites
// only those that are new or differ (image and manifest entry). It refuses to run while
// golden/ has uncommitted edits (git status), unless forced, so a regeneration is always
// a reviewable commit of its own. Every golden is rendered before anything is written:
// one bad scene leaves golden/ untouched. It holds golden/ locked throughout and commits the
// images and the manifest through a journal (golden_lock.h), so a second update waits and
// a killed one leaves all old files or, once the next golden command has looked, all new.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "image/compare.h"

namespace tracer {

struct UpdateRequest {
  std::string root = ".";
  std::string filter;  // ECMAScript regex searched in the name; empty matches all
  bool force = false;
  int threads = 0;
};

enum class GoldenChangeKind { New, Changed, Repaired, Unchanged };

struct GoldenChange {
  std::string name;
  GoldenChangeKind kind = GoldenChangeKind::Unchanged;
  std::optional<CompareResult> metrics;  // against the old image, when it was readable
};

// The paths under ROOT/golden that git reports as modified or untracked; InputError when
// git cannot tell (no git, not a checkout).
std::vector<std::string> uncommitted_golden_edits(const std::string& root);

// Throws InputError (nothing written) on refusal or bad input.
std::vector<GoldenChange> update_goldens(const UpdateRequest& request);

const char* change_name(GoldenChangeKind kind);

}  // namespace tracer
