#include "io/new_directory.h"

#include <stdlib.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "io/input_error.h"

namespace tracer {

std::filesystem::path make_new_directory(const std::filesystem::path& parent, const std::string& prefix) {
  const std::string pattern = (parent / (prefix + "XXXXXX")).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  if (::mkdtemp(name.data()) == nullptr)
    throw InputError(parent.string() + ": cannot create a working directory there: " + std::strerror(errno));
  return std::filesystem::path(name.data());
}

std::filesystem::path without_trailing_separator(const std::string& dir) {
  std::filesystem::path p = std::filesystem::path(dir).lexically_normal();
  if (!p.has_filename() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  return p;
}

}  // namespace tracer
