// The one check every command applies to the files it is about to write, before any work:
// an output may not be one of the command's inputs (the scene and every file it pulls in,
// images compared, parts merged, references) nor another of its outputs. Two paths are the
// same file when they are (an existing file reached through a symlink, `./` or `..`), or when
// they resolve to the same path once `.`, `..` and symlinks are followed (a file not yet made).
#pragma once
#include <string>
#include <vector>

namespace tracer {

struct NamedOutput {
  std::string path;
  std::string option;  // as the user wrote it: "-o", "--stats", "--diff" ...
};

bool same_file(const std::string& a, const std::string& b);

// InputError unless PATH can be written as a file: its directory exists, and PATH is not a
// directory, a device or a FIFO. Every output option's first check (images add their format's).
void check_output_location(const std::string& path, const std::string& option);

// InputError "PATH: OPTION names a file this command reads (INPUT); choose another name", or
// names the other output; outputs with an empty path are skipped.
void refuse_outputs_naming_inputs(const std::vector<NamedOutput>& outputs, const std::vector<std::string>& inputs);

}  // namespace tracer
