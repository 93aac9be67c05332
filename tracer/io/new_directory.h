// A directory this process creates for itself: a new name (mkdtemp's random suffix) that
// did not exist before, so removing it afterwards can never remove anything of the user's.
#pragma once
#include <filesystem>
#include <string>

namespace tracer {

// Creates parent/PREFIXxxxxxx (mode 0700) and returns its path; InputError naming parent
// when it cannot.
std::filesystem::path make_new_directory(const std::filesystem::path& parent, const std::string& prefix);

// A directory named on the command line, without a trailing separator ("out/" is "out"), so
// that its parent and its name are the ones the user meant.
std::filesystem::path without_trailing_separator(const std::string& dir);

}  // namespace tracer
