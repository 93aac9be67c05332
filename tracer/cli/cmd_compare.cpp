// `tracer compare A B`: two images compared with idiff's semantics (thresholds per channel,
// a percentage of pixels allowed to fail or warn), and optionally their difference image.
#include <cstdio>

#include "cli/command_registry.h"
#include "image/compare.h"
#include "image/image_io.h"
#include "io/output_paths.h"

namespace tracer {
namespace {

struct CompareCommand {
  std::string a, b, diff;
  CompareOptions options;
};

static int run_compare(const CompareCommand& cmd) {
  if (!cmd.diff.empty()) {
    check_image_output(cmd.diff, "--diff");
    refuse_outputs_naming_inputs({{cmd.diff, "--diff"}}, {cmd.a, cmd.b});
  }
  const Image a = read_image(cmd.a), b = read_image(cmd.b);
  const CompareResult r = compare_images(a, b, cmd.options);
  if (!cmd.diff.empty() && r.same_size) write_image(difference_image(a, b), cmd.diff);
  const char* verdict = r.verdict == Verdict::Pass ? "PASS" : r.verdict == Verdict::Warn ? "WARNING" : "FAIL";
  std::printf("%s: %s\n", verdict, describe(r).c_str());
  return r.verdict == Verdict::Fail ? 1 : 0;
}

}  // namespace

const RegisterCommand kCompareCommand(
    {"", "compare", "compare two images (idiff semantics)", [](CLI::App& app) {
       auto cmd = std::make_shared<CompareCommand>();
       app.add_option("a", cmd->a, "first image")->required();
       app.add_option("b", cmd->b, "second image")->required();
       app.add_option("--fail", cmd->options.fail, "per-channel failure threshold; 0 means bit-exact")
           ->check(decimal_in(0, 1e30));
       app.add_option("--failpercent", cmd->options.failpercent, "percentage of pixels allowed to fail")
           ->check(decimal_in(0, 100));
       app.add_option("--warn", cmd->options.warn, "per-channel warning threshold")->check(decimal_in(0, 1e30));
       app.add_option("--warnpercent", cmd->options.warnpercent, "percentage of pixels allowed to warn")
           ->check(decimal_in(0, 100));
       app.add_option("--diff", cmd->diff, "write |a - b| to this image");
       return [cmd] { return run_compare(*cmd); };
     }});

}  // namespace tracer
