// Every subcommand registers itself from its own file: where it sits ("" or a group such as
// "golden"), its name and one-line help, and a setup that declares its options on the CLI11
// app it is given and returns what runs it (the process exit code: 0 ok, 1 comparison
// failed, 2 bad input or error). main.cpp builds the command line from the registrations.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "cli/number_checks.h"
#include "io/thread_start.h"

namespace tracer {

using CommandRun = std::function<int()>;

struct CommandSpec {
  std::string group;  // "" for a top-level command, else "golden" or "bench"
  std::string name;
  std::string help;
  std::function<CommandRun(CLI::App&)> setup;
};

std::vector<CommandSpec>& command_registry();

// A static RegisterCommand in a command's file adds it before main() runs.
struct RegisterCommand {
  explicit RegisterCommand(CommandSpec spec) { command_registry().push_back(std::move(spec)); }
};

// The `--threads` option every CPU command takes: 0 (all) to 1024.
// --threads N: a count up to 1024 that this process can start (io/thread_start.h), checked
// before any work.
inline void add_threads_option(CLI::App& app, int& threads) {
  app.add_option("--threads", threads, "CPU threads, at most 1024 (default: all)")
      ->check(count_in(0, 1024))
      ->check(CLI::Validator(
          [](std::string& text) {
            const std::optional<uint64_t> n = parse_count(text, 1024);
            const std::string failure = n && *n > 1 ? thread_start_failure(static_cast<unsigned>(*n)) : "";
            return failure.empty() ? failure : "\"" + text + "\": " + failure;
          },
          "startable"));
}

}  // namespace tracer
