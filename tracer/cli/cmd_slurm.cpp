// `tracer slurm submit SCENE [render options] --parts N --dir DIR -o OUT [--wait]` and
// `tracer slurm wait DIR`: a render as one Slurm array job (task i renders a balanced sample
// range into DIR/part-I.partial) and one merge job that runs after every task succeeded
// (docs/distributed.md). `wait` follows the jobs, resubmits the ranges whose part is missing
// (a failed, cancelled or killed task) as a new array of those indices, and reports the result.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "cli/command_registry.h"
#include "cli/commands.h"
#include "cluster/slurm_client.h"
#include "image/image_io.h"
#include "io/input_error.h"
#include "io/output_paths.h"
#include "render/render_adaptive.h"
#include "scene/scene_loader.h"

namespace tracer {
namespace {

struct SlurmSubmitCommand {
  RenderCommand render;
  uint32_t parts = 0;
  std::string dir;
  std::vector<std::string> sbatch_args;
  uint32_t cpus_per_task = 1;
  bool wait = false;
  uint32_t retries = 2;
};

struct SlurmWaitCommand {
  std::string dir;
  uint32_t retries = 2;
};

std::string ranges_text(const SlurmJob& job, const std::vector<size_t>& tasks) {
  std::string text;
  for (const size_t t : tasks)
    text += (text.empty() ? "" : ", ") + std::to_string(job.ranges[t].begin) + ":" + std::to_string(job.ranges[t].end) +
            " (task " + std::to_string(t) + ", log logs/part-" + std::to_string(t) + ".log)";
  return text;
}

void wait_until_gone(const std::string& job_id) {
  while (job_in_queue(job_id)) std::this_thread::sleep_for(std::chrono::milliseconds(500));
}

void submit(SlurmJob& job, const std::vector<size_t>& tasks) {
  const std::string array = submit_render_array(job, tasks);
  job.array_jobs.push_back(array);
  job.merge_job = submit_merge(job, array);
  write_job_record(job);
  std::printf("submitted render array %s (%zu tasks) and merge job %s (after every task succeeded)\n", array.c_str(),
              tasks.size(), job.merge_job.c_str());
  std::fflush(stdout);
}

// Follows the latest submission to its end; resubmits missing ranges up to `retries` times.
int wait_for(SlurmJob& job, uint32_t retries) {
  for (;;) {
    wait_until_gone(job.array_jobs.back());
    const std::vector<size_t> missing = missing_parts(job);
    if (missing.empty()) break;
    std::fprintf(stderr, "tracer slurm: ranges missing after array %s: %s\n", job.array_jobs.back().c_str(),
                 ranges_text(job, missing).c_str());
    cancel_job(job.merge_job);  // Slurm cancels it too (--kill-on-invalid-dep); never merge a partial set
    if (retries == 0) {
      std::fprintf(stderr, "tracer slurm: no retries left; the merge did not run and %s was not written\n",
                   job.output.c_str());
      return 2;
    }
    --retries;
    submit(job, missing);
  }
  wait_until_gone(job.merge_job);
  const std::string state = job_state(job.merge_job);
  // Success only for the image this job's merge wrote: merge.sh marks it after the merge.
  if ((state.empty() || state == "COMPLETED") && std::filesystem::exists(merge_done_path(job)) &&
      std::filesystem::exists(job.output)) {
    std::printf("merge job %s: wrote %s\n", job.merge_job.c_str(), job.output.c_str());
    return 0;
  }
  std::fprintf(stderr, "tracer slurm: merge job %s ended %s; see %s/logs/merge.log\n", job.merge_job.c_str(),
               state.empty() ? "without an image" : state.c_str(), job.dir.c_str());
  return 2;
}

std::string this_executable() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw InputError("tracer slurm: cannot find the tracer executable: " + ec.message());
  return self.string();
}

int run_submit(const SlurmSubmitCommand& cmd) {
  if (!cmd.render.samples.empty()) throw InputError("--samples: tracer slurm chooses the ranges; give --parts");
  namespace fs = std::filesystem;
  const Scene scene =
      load_scene(cmd.render.scene, scene_overrides(cmd.render));  // bad input fails here, not on the cluster
  if (adaptive_render(scene.settings))
    throw InputError(cmd.render.scene +
                     ": noise_threshold, target_error: an adaptive render decides each pixel's samples from all "
                     "of them, so tracer slurm cannot split it into sample ranges; render it whole");
  SlurmJob job;
  job.dir = fs::absolute(cmd.dir).lexically_normal().string();
  job.scene = fs::absolute(cmd.render.scene).lexically_normal().string();
  job.output = fs::absolute(cmd.render.output).lexically_normal().string();
  // The merge job writes the image at the end, on the cluster: its name is checked here.
  check_image_output(cmd.render.output, "-o");
  refuse_outputs_naming_inputs({{cmd.render.output, "-o"}}, scene.files_read());
  job.spp = scene.settings.spp;
  job.ranges = balanced_ranges(job.spp, cmd.parts);
  job.sbatch_args = cmd.sbatch_args;
  job.cpus_per_task = cmd.cpus_per_task;
  std::vector<std::string> render_args;
  for (const auto& [name, text] : cmd.render.options)
    if (text) render_args.insert(render_args.end(), {option_flag(name), *text});
  const bool dir_existed = fs::exists(job.dir);  // then it was empty (write_job_scripts checks)
  write_job_scripts(job, this_executable(), render_args);
  std::vector<size_t> all(job.ranges.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  try {
    submit(job, all);
  } catch (...) {
    // A failed submission leaves nothing behind, so the corrected command works with the same
    // --dir: what was queued is cancelled, and what this command wrote is removed.
    for (const std::string& id : job.array_jobs) cancel_job(id);
    std::error_code ec;
    if (!dir_existed) {
      fs::remove_all(job.dir, ec);
    } else {
      for (const auto& entry : fs::directory_iterator(job.dir, ec)) fs::remove_all(entry.path(), ec);
    }
    throw;
  }
  if (!cmd.wait) {
    std::printf("follow it with: tracer slurm wait %s\n", job.dir.c_str());
    return 0;
  }
  return wait_for(job, cmd.retries);
}

const RegisterCommand kSlurmSubmit(
    {"slurm", "submit", "render as a Slurm array job of sample ranges plus a merge job", [](CLI::App& app) {
       auto cmd = std::make_shared<SlurmSubmitCommand>();
       add_scene_options(app, cmd->render);
       app.add_option("--parts", cmd->parts, "array tasks, each a balanced sample range")
           ->required()
           ->check(count_in(1, 10000));
       app.add_option("--dir", cmd->dir, "new job directory on the shared filesystem (scripts, parts, logs)")
           ->required();
       app.add_option("-o,--output", cmd->render.output, "the merged image (.exr, .png, ...)")->required();
       app.add_option("--sbatch", cmd->sbatch_args, "an sbatch option for every job, e.g. --sbatch=--partition=gpu")
           ->allow_extra_args(false);
       app.add_option("--cpus-per-task", cmd->cpus_per_task, "CPUs of each task (its render threads; default 1)")
           ->check(count_in(1, kMaxCpusPerTask));
       app.add_flag("--wait", cmd->wait, "wait for the image, resubmitting missing ranges (see slurm wait)");
       app.add_option("--retries", cmd->retries, "resubmissions of missing ranges with --wait (default 2)")
           ->check(count_in(0, 100));
       return [cmd] { return run_submit(*cmd); };
     }});

const RegisterCommand kSlurmWait(
    {"slurm", "wait", "follow a submitted render to its image, resubmitting missing ranges", [](CLI::App& app) {
       auto cmd = std::make_shared<SlurmWaitCommand>();
       app.add_option("dir", cmd->dir, "the job directory of tracer slurm submit")->required();
       app.add_option("--retries", cmd->retries, "resubmissions of missing ranges (default 2)")
           ->check(count_in(0, 100));
       return [cmd] {
         SlurmJob job = read_job_record(cmd->dir);
         return wait_for(job, cmd->retries);
       };
     }});

}  // namespace
}  // namespace tracer
