// tracer: render, inspect, compare and check goldens. Exit codes: 0 success, 1 comparison failed,
// 2 bad input (the message names the file and key) or any other error. Each command lives in
// its own cmd_*.cpp and registers itself (command_registry.h).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <new>
#include <string>

#include "cli/command_registry.h"
#include "cli/version_text.h"
#include "io/interrupt.h"
#include "io/standard_output.h"

namespace tracer {

std::vector<CommandSpec>& command_registry() {
  static std::vector<CommandSpec> commands;
  return commands;
}

// libstdc++ says "filesystem error: cannot OP: REASON [PATH1] [PATH2]"; the tracer says
// "PATH1: cannot OP (PATH2): REASON", as every other refusal names its file first.
std::string describe_filesystem_error(const std::filesystem::filesystem_error& e) {
  const std::string what = e.what(), reason = e.code().message();
  const std::string prefix = "filesystem error: ";
  std::string operation = what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
  operation = operation.substr(0, operation.find(": " + reason));
  std::string text = e.path1().empty() ? operation : e.path1().string() + ": " + operation;
  if (!e.path2().empty()) text += " (" + e.path2().string() + ")";
  return text + ": " + reason;
}

namespace {

int run_command(int argc, char** argv) {
  CLI::App app{"tracer: a deterministic ray tracer"};
  app.require_subcommand(1);
  app.set_version_flag("--version", [] { return version_text(); });
  const std::map<std::string, std::string> group_help = {
      {"golden", "golden-image regression checks (docs/golden.md)"},
      {"bench", "benchmarks: speed against a baseline measured in the same run"},
      {"slurm", "renders split over a Slurm cluster (docs/distributed.md)"},
      {"audit", "checks of the compiled CUDA kernels and of the source (docs/cuda.md)"}};
  std::map<std::string, CLI::App*> groups;
  std::vector<CommandSpec> commands = command_registry();
  std::sort(commands.begin(), commands.end(), [](const CommandSpec& a, const CommandSpec& b) {
    return std::tie(a.group, a.name) < std::tie(b.group, b.name);
  });
  std::vector<std::pair<CLI::App*, CommandRun>> runs;
  for (const CommandSpec& c : commands) {
    CLI::App* parent = &app;
    if (!c.group.empty()) {
      CLI::App*& group = groups[c.group];
      if (!group) {
        group = app.add_subcommand(c.group, group_help.at(c.group));
        group->require_subcommand(1);
      }
      parent = group;
    }
    CLI::App* sub = parent->add_subcommand(c.name, c.help);
    runs.emplace_back(sub, c.setup(*sub));
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    for (const auto& [sub, run] : runs)
      if (*sub) return run();
  } catch (const Interrupted& e) {  // what the command made is removed; end as the signal asked
    std::fprintf(stderr, "tracer: %s; nothing was written\n", e.what());
    end_by_signal(e.signal());
  } catch (const std::bad_alloc&) {  // the input asked for more memory than the machine has
    std::string command = "tracer";
    for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
    std::fprintf(stderr, "error: out of memory: `%s` needs more memory than this machine gives\n",
                 command.substr(0, 400).c_str());
  } catch (const std::filesystem::filesystem_error& e) {  // named as the tracer names files, not as libstdc++ does
    std::fprintf(stderr, "error: %s\n", describe_filesystem_error(e).c_str());
  } catch (const std::exception& e) {  // InputError, DeviceUnavailable, CUDA errors, I/O
    std::fprintf(stderr, "error: %s\n", e.what());
  }
  return 2;
}

}  // namespace
}  // namespace tracer

int main(int argc, char** argv) { return tracer::exit_code_after_flushing_stdout(tracer::run_command(argc, argv)); }
