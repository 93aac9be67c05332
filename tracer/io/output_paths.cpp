#include "io/output_paths.h"

#include <filesystem>

#include "io/input_error.h"

namespace fs = std::filesystem;

namespace tracer {

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec)) return true;
  const fs::path ra = fs::weakly_canonical(fs::absolute(a), ec);
  if (ec) return false;
  const fs::path rb = fs::weakly_canonical(fs::absolute(b), ec);
  return !ec && ra == rb;
}

void check_output_location(const std::string& path, const std::string& option) {
  const fs::path p(path);
  const fs::path dir = p.parent_path().empty() ? "." : p.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(path + ": " + option + ": output directory does not exist");
  const fs::file_status status = fs::status(p, ec);
  if (fs::is_directory(status)) throw InputError(path + ": " + option + " names a directory; name a file");
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw InputError(path + ": " + option + " names a device, FIFO or socket; name a file");
}

void refuse_outputs_naming_inputs(const std::vector<NamedOutput>& outputs, const std::vector<std::string>& inputs) {
  for (size_t i = 0; i < outputs.size(); ++i) {
    const NamedOutput& out = outputs[i];
    if (out.path.empty()) continue;
    for (const std::string& input : inputs)
      if (!input.empty() && same_file(out.path, input))
        throw InputError(out.path + ": " + out.option + " names a file this command reads (" + input +
                         "); choose another name");
    for (size_t j = 0; j < i; ++j)
      if (!outputs[j].path.empty() && same_file(out.path, outputs[j].path))
        throw InputError(out.path + ": " + out.option + " names the same file as " + outputs[j].option +
                         "; choose another name");
  }
}

}  // namespace tracer
