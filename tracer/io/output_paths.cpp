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
