// The parts of `tracer slurm` that need no cluster: balanced sample ranges, the job
// directory's scripts and record (tracer/cluster/slurm_job.h). The cluster runs: tests/slurm/.
#include <gtest/gtest.h>

#include <fstream>

#include "cluster/slurm_job.h"
#include "io/input_error.h"
#include "test_util.h"

namespace tracer {
namespace {

namespace fs = std::filesystem;

TEST(SlurmJob, RangesCoverEverySampleOnceAndDifferByAtMostOne) {
  for (const uint32_t spp : {1u, 7u, 64u, 1000u, 4294967295u})
    for (const uint32_t parts : {1u, 2u, 3u, 7u, 8u, 1000u}) {
      if (parts > spp) {
        EXPECT_THROW(balanced_ranges(spp, parts), InputError);
        continue;
      }
      const std::vector<SampleRange> ranges = balanced_ranges(spp, parts);
      ASSERT_EQ(ranges.size(), parts);
      uint32_t next = 0, smallest = UINT32_MAX, largest = 0;
      for (const SampleRange& r : ranges) {
        EXPECT_EQ(r.begin, next);
        EXPECT_LT(r.begin, r.end);
        smallest = std::min(smallest, r.end - r.begin);
        largest = std::max(largest, r.end - r.begin);
        next = r.end;
      }
      EXPECT_EQ(next, spp);
      EXPECT_LE(largest - smallest, 1u) << spp << " spp in " << parts;
    }
  EXPECT_THROW(balanced_ranges(8, 0), InputError);
}

TEST(SlurmJob, ScriptsAndRecordRoundTrip) {
  const fs::path dir = test::temp_dir("slurm-job");
  SlurmJob job;
  job.dir = (dir / "job").string();
  job.scene = "/shared/scene's.json";
  job.output = "/shared/out.exr";
  job.spp = 10;
  job.ranges = balanced_ranges(10, 3);
  job.sbatch_args = {"--partition=render", "--time=10"};
  job.array_jobs = {"41", "57"};
  job.merge_job = "58";
  write_job_scripts(job, "/opt/tracer/bin/tracer", {"--spp", "10"});
  write_job_record(job);
  std::stringstream render;
  render << std::ifstream(dir / "job/render.sh").rdbuf();
  EXPECT_NE(render.str().find("ranges=(0:3 3:6 6:10)"), std::string::npos) << render.str();
  EXPECT_NE(render.str().find("'/shared/scene'\\''s.json' '--spp' '10'"), std::string::npos) << render.str();
  EXPECT_TRUE(fs::exists(dir / "job/merge.sh"));
  EXPECT_TRUE(fs::is_directory(dir / "job/logs"));
  const SlurmJob back = read_job_record(job.dir);
  EXPECT_EQ(back.scene, job.scene);
  EXPECT_EQ(back.ranges.size(), 3u);
  EXPECT_EQ(back.sbatch_args, job.sbatch_args);
  EXPECT_EQ(back.array_jobs, job.array_jobs);
  EXPECT_EQ(back.merge_job, "58");
  EXPECT_EQ(missing_parts(back), (std::vector<size_t>{0, 1, 2}));
  EXPECT_THROW(write_job_scripts(job, "/opt/tracer/bin/tracer", {}), InputError);  // not empty any more
  fs::remove_all(dir);
}

// A scheduler stand-in on PATH: `sbatch` that fails (as a bad --partition would) and then one
// that accepts, printing a job id. A failed submit left its job directory (scripts, logs)
// behind, so the corrected command was refused: "the job directory must be new or empty".
TEST(SlurmJob, AFailedSubmitLeavesNothingBehind) {
  const fs::path dir = test::temp_dir("slurm-submit");
  fs::create_directories(dir / "bin");
  const auto stand_in = [&](const std::string& body) {
    std::ofstream(dir / "bin" / "sbatch") << "#!/bin/sh\n" << body << "\n";
    fs::permissions(dir / "bin" / "sbatch", fs::perms::owner_all);
  };
  std::ofstream(dir / "s.json")
      << R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40},
           "film": {"width": 4, "height": 4}, "render": {"spp": 2}, "materials": {}, "shapes": []})";
  const std::string submit = "PATH=" + (dir / "bin").string() + ":$PATH " + TRACER_BINARY + " slurm submit " +
                             (dir / "s.json").string() + " --parts 2 --dir " + (dir / "job").string() + " -o " +
                             (dir / "out.exr").string();
  stand_in("echo 'sbatch: error: invalid partition specified: nosuch' >&2; exit 1");
  std::string out;
  EXPECT_EQ(test::run_command(submit, &out), 2) << out;
  EXPECT_NE(out.find("invalid partition"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "job")) << "a failed submit left its job directory";
  fs::create_directories(dir / "job");  // an empty directory given as --dir stays, emptied
  EXPECT_EQ(test::run_command(submit, &out), 2) << out;
  EXPECT_TRUE(fs::is_directory(dir / "job") && fs::is_empty(dir / "job"));
  stand_in("echo 4242");
  EXPECT_EQ(test::run_command(submit, &out), 0) << out;
  EXPECT_TRUE(fs::exists(dir / "job" / "job.json")) << out;
  fs::remove_all(dir);
}

// job.json is input too: `slurm wait` on a record with no array job crashed (it took the last
// of none), and one with no ranges blamed "--parts 0". Each broken key is named.
TEST(SlurmJob, EveryKeyOfTheRecordIsChecked) {
  const fs::path dir = test::temp_dir("slurm-record");
  SlurmJob job;
  job.dir = dir.string();
  job.scene = (dir / "s.json").string();
  job.output = (dir / "out.exr").string();
  job.spp = 8;
  job.ranges = balanced_ranges(8, 2);
  job.array_jobs = {"11"};
  job.merge_job = "12";
  write_job_record(job);
  const std::string good = test::read_file(dir / "job.json");
  const std::vector<std::pair<std::string, std::string>> broken = {
      {R"("array_jobs": [
    "11"
  ])",
       R"("array_jobs": [])"},
      {R"("array_jobs": [
    "11"
  ])",
       R"("array_jobs": [""])"},
      {R"("merge_job": "12")", R"("merge_job": "")"},
      {R"("spp": 8)", R"("spp": 0)"},
      {R"("ranges": [)", R"("ranges": [[0, 1], )"},
      {R"("spp": 8)", R"("spp": 4294967304)"},  // 2^32 + 8 was read as 8
      {R"("cpus_per_task": 1)", R"("cpus_per_task": 4294967297)"},
      {R"("cpus_per_task": 1)", R"("cpus_per_task": 0)"},
  };
  const std::vector<std::string> keys = {"array_jobs", "array_jobs", "merge_job",     "spp",
                                         "ranges",     "spp",        "cpus_per_task", "cpus_per_task"};
  for (size_t i = 0; i < broken.size(); ++i) {
    std::string text = good;
    const size_t at = text.find(broken[i].first);
    ASSERT_NE(at, std::string::npos) << broken[i].first << " in\n" << good;
    text.replace(at, broken[i].first.size(), broken[i].second);
    std::ofstream(dir / "job.json") << text;
    std::string out;
    EXPECT_EQ(test::run_tracer("slurm wait " + dir.string() + " --retries 0", &out), 2) << text << out;
    EXPECT_NE(out.find("job.json: " + keys[i]), std::string::npos) << keys[i] << ": " << out;
  }
  fs::remove_all(dir);
}

// `slurm wait` reported success whenever a file stood at -o after the merge job left the queue,
// an older image included. It now needs merge.done, which merge.sh writes after its merge.
// Stand-ins on PATH: sbatch prints a job id, squeue finds nothing queued, scontrol knows no job.
TEST(SlurmJob, WaitReportsOnlyAnImageThisJobWrote) {
  const fs::path dir = test::temp_dir("slurm-wait");
  fs::create_directories(dir / "bin");
  for (const auto& [name, body] :
       {std::pair{"sbatch", "echo 77"}, std::pair{"squeue", "exit 0"}, std::pair{"scontrol", "exit 1"}}) {
    std::ofstream(dir / "bin" / name) << "#!/bin/sh\n" << body << "\n";
    fs::permissions(dir / "bin" / name, fs::perms::owner_all);
  }
  std::ofstream(dir / "s.json")
      << R"({"format": "tracer-scene/1", "camera": {"from": [0, 0, 3], "to": [0, 0, 0], "vfov": 40},
           "film": {"width": 4, "height": 4}, "render": {"spp": 2}, "materials": {}, "shapes": []})";
  const std::string path = "PATH=" + (dir / "bin").string() + ":$PATH ";
  std::string out;
  ASSERT_EQ(test::run_command(path + TRACER_BINARY + " slurm submit " + (dir / "s.json").string() +
                                  " --parts 1 --dir " + (dir / "job").string() + " -o " + (dir / "out.exr").string(),
                              &out),
            0)
      << out;
  ASSERT_EQ(test::run_tracer("render " + (dir / "s.json").string() + " --quiet --samples 0:2 -o " +
                                 (dir / "job" / "part-0.partial").string(),
                             &out),
            0)
      << out;
  std::ofstream(dir / "out.exr") << "an image from an earlier render";
  const std::string wait = path + TRACER_BINARY + " slurm wait " + (dir / "job").string() + " --retries 0";
  EXPECT_EQ(test::run_command(wait, &out), 2) << out;
  EXPECT_NE(out.find("without an image"), std::string::npos) << out;
  ASSERT_EQ(test::run_command("bash " + (dir / "job" / "merge.sh").string(), &out), 0) << out;  // the merge job
  EXPECT_TRUE(fs::exists(dir / "job" / "merge.done"));
  EXPECT_EQ(test::run_command(wait, &out), 0) << out;
  EXPECT_NE(out.find("wrote " + (dir / "out.exr").string()), std::string::npos) << out;
  // A state the tracer does not know (Slurm adds some) is a failure that names it, image or not.
  std::ofstream(dir / "bin" / "scontrol") << "#!/bin/sh\necho 'JobId=77 JobState=SPECIAL_EXIT Reason=None'\n";
  EXPECT_EQ(test::run_command(wait, &out), 2) << out;
  EXPECT_NE(out.find("merge job 77 ended SPECIAL_EXIT"), std::string::npos) << out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tracer
