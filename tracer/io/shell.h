// Running a shell command from the CLI (git for the golden update's safety check, sbatch) and
// quoting arguments for commands it prints for the user to run.
#pragma once
#include <string>

namespace tracer {

std::string shell_quote(const std::string& s);  // 'it'\''s' style: safe in sh

// Runs `command` with sh and returns its exit status (-1 if it did not exit normally);
// its standard output goes to `output`.
int run_capture(const std::string& command, std::string& output);

}  // namespace tracer
