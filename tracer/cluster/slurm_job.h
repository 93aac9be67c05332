// A render split over a Slurm array job (docs/distributed.md): the job directory on the shared
// filesystem holds render.sh (array task i renders the samples ranges[i] into part-I.partial),
// merge.sh (tracer merge of every part into the output), logs/ and job.json, the record that
// `tracer slurm wait` reads. No scheduling of our own: Slurm runs the tasks, the retries
// resubmit the missing indices of the same array script.
#pragma once
#include <string>
#include <vector>

#include "render/film_buffer.h"

namespace tracer {

constexpr uint32_t kMaxCpusPerTask = 1024;  // --cpus-per-task, and the record's cpus_per_task

struct SlurmJob {
  std::string dir;            // absolute job directory (shared)
  std::string scene, output;  // absolute paths
  uint32_t spp = 0;
  std::vector<SampleRange> ranges;       // task i renders ranges[i]
  std::vector<std::string> sbatch_args;  // passed to every sbatch call (partition, time, account)
  uint32_t cpus_per_task = 1;
  std::vector<std::string> array_jobs;  // the array job of each submission, the first one first
  std::string merge_job;                // the merge job of the latest submission
};

// Sample ranges of `parts` tasks whose sizes differ by at most one sample; parts <= spp.
std::vector<SampleRange> balanced_ranges(uint32_t spp, uint32_t parts);

std::string part_path(const SlurmJob& job, size_t task);  // DIR/part-I.partial
std::string merge_done_path(const SlurmJob& job);         // DIR/merge.done, written by merge.sh after the merge

// Creates DIR (it must not exist or be empty) with logs/, render.sh and merge.sh; `render_args`
// are the render options as given on the command line, `tracer` this executable.
void write_job_scripts(const SlurmJob& job, const std::string& tracer, const std::vector<std::string>& render_args);

void write_job_record(const SlurmJob& job);        // DIR/job.json
SlurmJob read_job_record(const std::string& dir);  // InputError naming the file and key

// The tasks whose part file is missing, unreadable or not the range it should hold.
std::vector<size_t> missing_parts(const SlurmJob& job);

}  // namespace tracer
