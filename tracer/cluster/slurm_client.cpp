#include "cluster/slurm_client.h"

#include <filesystem>

#include "io/input_error.h"
#include "io/shell.h"

namespace tracer {
namespace {

// Runs a Slurm command; its stdout without the trailing newline, or InputError with what it said.
std::string slurm(const std::string& command) {
  std::string out;
  const int status = run_capture(command + " 2>&1", out);
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  if (status != 0) throw InputError("slurm: `" + command + "` failed: " + out);
  return out;
}

std::string sbatch_common(const SlurmJob& job) {
  std::string args;
  for (const std::string& a : job.sbatch_args) args += " " + shell_quote(a);
  return args;
}

}  // namespace

std::string submit_render_array(const SlurmJob& job, const std::vector<size_t>& tasks) {
  std::string indices;
  for (const size_t t : tasks) indices += (indices.empty() ? "" : ",") + std::to_string(t);
  const std::filesystem::path dir(job.dir);
  return slurm("sbatch --parsable --requeue --job-name=tracer-render --array=" + indices + " --cpus-per-task=" +
               std::to_string(job.cpus_per_task) + " --output=" + shell_quote((dir / "logs" / "part-%a.log").string()) +
               sbatch_common(job) + " " + shell_quote((dir / "render.sh").string()));
}

std::string submit_merge(const SlurmJob& job, const std::string& array_job) {
  const std::filesystem::path dir(job.dir);
  return slurm("sbatch --parsable --job-name=tracer-merge --dependency=afterok:" + array_job +
               " --kill-on-invalid-dep=yes --output=" + shell_quote((dir / "logs" / "merge.log").string()) +
               sbatch_common(job) + " " + shell_quote((dir / "merge.sh").string()));
}

bool job_in_queue(const std::string& job_id) {
  std::string out;
  run_capture("squeue -h -j " + shell_quote(job_id) + " -o %i 2>/dev/null", out);
  return out.find_first_not_of(" \n") != std::string::npos;
}

std::string job_state(const std::string& job_id) {
  std::string out;
  if (run_capture("scontrol -o show job " + shell_quote(job_id) + " 2>/dev/null", out) != 0) return "";
  const size_t at = out.find("JobState=");
  if (at == std::string::npos) return "";
  return out.substr(at + 9, out.find(' ', at) - at - 9);
}

void cancel_job(const std::string& job_id) {
  std::string ignored;
  run_capture("scancel " + shell_quote(job_id) + " 2>/dev/null", ignored);
}

}  // namespace tracer
