// The Slurm commands the front end runs (sbatch, squeue, scontrol, scancel), through sh; an
// InputError carries Slurm's own message when a command fails.
#pragma once
#include <string>
#include <vector>

#include "cluster/slurm_job.h"

namespace tracer {

// Submits the array of `tasks` (indices into job.ranges) with --requeue; returns the job id.
std::string submit_render_array(const SlurmJob& job, const std::vector<size_t>& tasks);
// Submits merge.sh after every task of `array_job` succeeded (afterok; cancelled by Slurm when
// one fails: --kill-on-invalid-dep); returns the job id.
std::string submit_merge(const SlurmJob& job, const std::string& array_job);

bool job_in_queue(const std::string& job_id);      // pending, running, requeued or completing
std::string job_state(const std::string& job_id);  // COMPLETED, FAILED, CANCELLED...; "" once purged
void cancel_job(const std::string& job_id);

}  // namespace tracer
