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
inline void add_threads_option(CLI::App& app, int& threads) {
  app.add_option("--threads", threads, "CPU threads, at most 1024 (default: all)")->check(count_in(0, 1024));
}

}  // namespace tracer
