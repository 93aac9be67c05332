#include "audit/ptx_directory.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "io/input_error.h"
#include "io/new_directory.h"
#include "io/output_batch.h"

namespace fs = std::filesystem;

namespace tracer {
PtxDirectory::PtxDirectory(const std::string& dir, bool owned_by_build) : owned_by_build_(owned_by_build) {
  const fs::path p = without_trailing_separator(dir);
  dir_ = p.string();
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(p, ec);
  if (fs::exists(st)) {
    if (fs::is_symlink(st) || !fs::is_directory(st))
      throw InputError(dir_ + " (--ptx-dir): not a directory the audit made (a link or another kind of file)");
    if (!owned_by_build && !fs::exists(fs::symlink_status(p / kPtxDirectoryMarker)))
      throw InputError(dir_ + " (--ptx-dir): a directory without " + kPtxDirectoryMarker +
                       ", so not one an earlier audit made: give a new path");
  }
  const fs::path parent = p.has_parent_path() ? p.parent_path() : fs::path(".");
  fs::create_directories(parent, ec);
  if (!fs::is_directory(parent)) throw InputError(parent.string() + ": cannot create the directory (--ptx-dir)");
  staging_ = make_new_directory(parent, p.filename().string() + ".partial-").string();
  try {
    write_file_atomically((fs::path(staging_) / kPtxDirectoryMarker).string(),
                          "PTX of `tracer audit cuda`; the next audit replaces this directory\n");
  } catch (const InputError& e) {
    fs::remove_all(staging_, ec);  // the destructor does not run for a constructor that throws
    throw InputError(std::string(e.what()) + " (--ptx-dir " + dir_ + ")");
  }
}

PtxDirectory::~PtxDirectory() {
  if (kept_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);  // a directory this process made
}

void PtxDirectory::keep() {
  std::error_code ec;
  if (fs::exists(fs::symlink_status(dir_))) {
    // Checked again: DIR is an earlier audit's directory, which remove_all removes without following links.
    if ((!owned_by_build_ && !fs::exists(fs::symlink_status(fs::path(dir_) / kPtxDirectoryMarker))) ||
        fs::is_symlink(fs::symlink_status(dir_)))
      throw std::runtime_error(dir_ + " (--ptx-dir) changed during the audit into something it did not make");
    fs::remove_all(dir_, ec);
    if (ec) throw std::runtime_error(dir_ + " (--ptx-dir): cannot remove the earlier audit's PTX: " + ec.message());
  }
  fs::rename(staging_, dir_, ec);
  if (ec) throw std::runtime_error(dir_ + " (--ptx-dir): cannot move the PTX into place: " + ec.message());
  kept_ = true;
}

}  // namespace tracer
