// Where `tracer audit cuda` keeps its PTX (--ptx-dir DIR). nvcc writes into a new directory
// beside DIR (io/new_directory.h: a name nothing can have planted, so no symlink, FIFO or
// device inside it receives PTX), which replaces DIR once every module is written. DIR may be
// absent or an earlier audit's (it holds the marker file kPtxDirectoryMarker, or it is the
// build's own BUILD/ptx-audit, `owned_by_build`); anything else
// (a symlink, a file, a device, a directory of the user's) is refused before any work, so
// the audit writes through no link and deletes nothing it did not make.
#pragma once
#include <string>

namespace tracer {

inline constexpr const char* kPtxDirectoryMarker = ".tracer-audit-ptx";

class PtxDirectory {
 public:
  // InputError naming DIR (--ptx-dir) when it cannot be used.
  PtxDirectory(const std::string& dir, bool owned_by_build);
  ~PtxDirectory();  // removes the staging directory unless kept
  PtxDirectory(const PtxDirectory&) = delete;
  PtxDirectory& operator=(const PtxDirectory&) = delete;

  // Where the PTX is written during the run.
  const std::string& staging() const { return staging_; }
  // Where it is kept.
  const std::string& path() const { return dir_; }

  // Replaces DIR with the staging directory; std::runtime_error naming DIR when it cannot.
  void keep();

 private:
  std::string dir_, staging_;
  bool owned_by_build_, kept_ = false;
};

}  // namespace tracer
