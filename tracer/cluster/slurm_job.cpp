#include "cluster/slurm_job.h"

#include <nlohmann/json.hpp>
#include <sys/stat.h>

#include <filesystem>

#include "io/input_error.h"
#include "io/json_reader.h"
#include "io/output_batch.h"
#include "io/shell.h"
#include "io/text_file.h"
#include "render/partial_file.h"

namespace tracer {
namespace {

const char kRecordFormat[] = "tracer-slurm-job/1";

std::string quoted(const std::vector<std::string>& args) {
  std::string out;
  for (const std::string& a : args) out += " " + shell_quote(a);
  return out;
}

void write_script(const std::string& path, const std::string& text) {
  write_file_atomically(path, text);
  if (::chmod(path.c_str(), 0755) != 0) throw InputError(path + ": cannot make the script executable");
}

}  // namespace

std::vector<SampleRange> balanced_ranges(uint32_t spp, uint32_t parts) {
  if (parts == 0 || parts > spp)
    throw InputError("--parts " + std::to_string(parts) + ": expected 1 to spp (" + std::to_string(spp) + ")");
  std::vector<SampleRange> ranges;
  for (uint64_t i = 0; i < parts; ++i)
    ranges.push_back({static_cast<uint32_t>(i * spp / parts), static_cast<uint32_t>((i + 1) * spp / parts)});
  return ranges;
}

std::string merge_done_path(const SlurmJob& job) { return (std::filesystem::path(job.dir) / "merge.done").string(); }

std::string part_path(const SlurmJob& job, size_t task) {
  return (std::filesystem::path(job.dir) / ("part-" + std::to_string(task) + ".partial")).string();
}

void write_job_scripts(const SlurmJob& job, const std::string& tracer, const std::vector<std::string>& render_args) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(job.dir) && !fs::is_empty(job.dir, ec))
    throw InputError(job.dir + ": the job directory must be new or empty");
  fs::create_directories(fs::path(job.dir) / "logs", ec);
  if (ec) throw InputError(job.dir + ": cannot create the job directory: " + ec.message());
  std::string ranges;
  for (const SampleRange& r : job.ranges) ranges += " " + std::to_string(r.begin) + ":" + std::to_string(r.end);
  write_script((fs::path(job.dir) / "render.sh").string(),
               "#!/usr/bin/env bash\n"
               "# tracer slurm: array task I renders samples ranges[I] of the scene into part-I.partial.\n"
               "set -euo pipefail\n"
               "ranges=(" +
                   ranges.substr(1) +
                   ")\n"
                   "i=$SLURM_ARRAY_TASK_ID\n"
                   "exec " +
                   shell_quote(tracer) + " render " + shell_quote(job.scene) + quoted(render_args) +
                   " --quiet --threads \"${SLURM_CPUS_PER_TASK:-1}\" --samples \"${ranges[$i]}\" -o " +
                   shell_quote(job.dir) + "/part-\"$i\".partial\n");
  std::vector<std::string> parts;
  for (size_t i = 0; i < job.ranges.size(); ++i) parts.push_back(part_path(job, i));
  write_script((fs::path(job.dir) / "merge.sh").string(),
               "#!/usr/bin/env bash\n"
               "# tracer slurm: adds every part into the image; tracer merge refuses gaps, overlaps and\n"
               "# parts of another render, and then writes nothing. merge.done tells `tracer slurm wait`\n"
               "# that this job wrote the image (not an older file at the same path).\n" +
                   shell_quote(tracer) + " merge" + quoted(parts) + " -o " + shell_quote(job.output) + " && : > " +
                   shell_quote(merge_done_path(job)) + "\n");
}

void write_job_record(const SlurmJob& job) {
  Json ranges = Json::array();
  for (const SampleRange& r : job.ranges) ranges.push_back({r.begin, r.end});
  const Json record = {{"format", kRecordFormat},
                       {"scene", job.scene},
                       {"output", job.output},
                       {"spp", job.spp},
                       {"ranges", ranges},
                       {"sbatch_args", job.sbatch_args},
                       {"cpus_per_task", job.cpus_per_task},
                       {"array_jobs", job.array_jobs},
                       {"merge_job", job.merge_job}};
  write_file_atomically((std::filesystem::path(job.dir) / "job.json").string(), record.dump(2) + "\n");
}

SlurmJob read_job_record(const std::string& dir) {
  const std::string path = (std::filesystem::path(dir) / "job.json").string();
  const Json doc = parse_json_text(read_text_file(path, "Slurm job record", 1 << 20), path);
  JsonObject obj(doc, "", path);
  if (obj.string("format") != kRecordFormat) obj.fail("format", "expected \"" + std::string(kRecordFormat) + "\"");
  SlurmJob job;
  job.dir = std::filesystem::absolute(dir).lexically_normal().string();
  job.scene = obj.string("scene");
  job.output = obj.string("output");
  job.spp = obj.unsigned_integer_32("spp");  // 2^32 + 1 was read as 1
  job.cpus_per_task = obj.unsigned_integer_32("cpus_per_task");
  job.merge_job = obj.string("merge_job");
  if (job.spp == 0) obj.fail("spp", "expected at least 1");
  if (job.cpus_per_task == 0 || job.cpus_per_task > kMaxCpusPerTask)
    obj.fail("cpus_per_task", "expected 1 to " + std::to_string(kMaxCpusPerTask) + " (the --cpus-per-task limit)");
  if (job.merge_job.empty()) obj.fail("merge_job", "expected the merge job's id");
  // The ranges are the balanced ones submit wrote, entry by entry.
  const Json& ranges = obj.get("ranges");
  if (!ranges.is_array() || ranges.empty() || ranges.size() > job.spp)
    obj.fail("ranges", "expected 1 to spp (" + std::to_string(job.spp) + ") sample ranges");
  job.ranges = balanced_ranges(job.spp, static_cast<uint32_t>(ranges.size()));
  for (size_t i = 0; i < job.ranges.size(); ++i)
    if (ranges[i] != Json::array({job.ranges[i].begin, job.ranges[i].end}))
      obj.fail("ranges", "entry " + std::to_string(i) + " is not [" + std::to_string(job.ranges[i].begin) + ", " +
                             std::to_string(job.ranges[i].end) + "], the balanced range submit wrote");
  for (const auto& [key, into] :
       {std::pair{"sbatch_args", &job.sbatch_args}, std::pair{"array_jobs", &job.array_jobs}}) {
    const Json& list = obj.get(key);
    if (!list.is_array()) obj.fail(key, "expected an array of strings");
    for (const Json& v : list) {
      if (!v.is_string()) obj.fail(key, "expected strings");
      into->push_back(v.get<std::string>());
    }
  }
  if (job.array_jobs.empty()) obj.fail("array_jobs", "expected at least one array job id");
  for (const std::string& id : job.array_jobs)
    if (id.empty()) obj.fail("array_jobs", "expected job ids, got an empty one");
  obj.finish();
  return job;
}

std::vector<size_t> missing_parts(const SlurmJob& job) {
  std::vector<size_t> missing;
  for (size_t i = 0; i < job.ranges.size(); ++i) {
    try {
      const Partial part = read_partial(part_path(job, i));
      if (part.film.range.begin != job.ranges[i].begin || part.film.range.end != job.ranges[i].end)
        missing.push_back(i);
    } catch (const InputError&) {
      missing.push_back(i);
    }
  }
  return missing;
}

}  // namespace tracer
