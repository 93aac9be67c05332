// Fuzz target: a Slurm job record (cluster/slurm_job.h) through read_job_record, what `tracer
// slurm wait` trusts: every key, the job ids and the balanced sample ranges.
#include "cluster/slurm_job.h"
#include "fuzz_sandbox.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  tracer::fuzz::write_input("job.json", data, size);
  tracer::fuzz::expect_clean_error([&] { tracer::read_job_record(tracer::fuzz::sandbox().string()); });
  return 0;
}
