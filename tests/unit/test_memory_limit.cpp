// The memory a process may use (io/memory_limit.h) and the stream schedule's check against it
// (render/stream_memory.h): a memory cgroup's limit (Slurm's --mem, a container's) counts, not
// only the machine's memory. The stream's states for 2^20 samples in flight (about 800 MB for
// the Cornell box) were allocated under a 256 MiB cgroup limit (the kernel then kills the
// process), and the runner's CPU stream had no check at all.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/memory_limit.h"
#include "test_util.h"

namespace fs = std::filesystem;

namespace tracer {
namespace {

void put(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

TEST(MemoryLimit, TheLowestLimitOfTheCgroupAndItsParentsCounts) {
  const fs::path dir = test::temp_dir("memory-limit");
  put(dir / "v2.cgroup", "0::/job/step\n");
  put(dir / "fs/job/step/memory.max", "max\n");
  put(dir / "fs/job/memory.max", "1048576\n");
  MemoryLimit limit = memory_limit((dir / "v2.cgroup").string(), (dir / "fs").string());
  EXPECT_EQ(limit.bytes, 1048576u);
  EXPECT_NE(limit.source.find((dir / "fs/job/memory.max").string()), std::string::npos) << limit.source;

  put(dir / "v1.cgroup", "5:cpu,cpuacct:/x\n4:memory:/slurm/uid_0/job_7\n0::/\n");
  put(dir / "fs/memory/slurm/uid_0/job_7/memory.limit_in_bytes", "2097152\n");
  put(dir / "fs/memory/slurm/memory.limit_in_bytes", "9223372036854771712\n");
  limit = memory_limit((dir / "v1.cgroup").string(), (dir / "fs").string());
  EXPECT_EQ(limit.bytes, 2097152u);

  // No cgroup file, unreadable values, a limit above the machine's memory: the machine's.
  put(dir / "fs/memory/slurm/uid_0/job_7/memory.limit_in_bytes", "lots\n");
  const MemoryLimit machine = memory_limit((dir / "missing").string(), (dir / "fs").string());
  EXPECT_EQ(machine.source, "this machine's memory");
  EXPECT_GT(machine.bytes, 0u);
  EXPECT_EQ(memory_limit((dir / "v1.cgroup").string(), (dir / "fs").string()).bytes, machine.bytes);
  fs::remove_all(dir);
}

// Runs `command` in a new memory cgroup limited to 256 MiB (v1 or v2); 77 where none can be made.
int run_in_small_cgroup(const std::string& command, std::string& output) {
  const std::string script = R"(
for cg in /sys/fs/cgroup/memory/tracer-test-$$:memory.limit_in_bytes /sys/fs/cgroup/tracer-test-$$:memory.max; do
  dir=${cg%:*}; file=${cg##*:}
  mkdir "$dir" 2>/dev/null || continue
  if echo 268435456 > "$dir/$file" 2>/dev/null; then
    sh -c "echo \$\$ > $dir/cgroup.procs || exit 77; exec $1"; status=$?
    rmdir "$dir"; exit $status
  fi
  rmdir "$dir"
done
exit 77)";
  const fs::path file = test::temp_dir("cgroup-run") / "run.sh";
  std::ofstream(file) << script;
  const int status = test::run_command("sh " + file.string() + " '" + command + "'", &output);
  fs::remove_all(file.parent_path());
  return status;
}

TEST(MemoryLimit, StreamWidthsBeyondTheCgroupsLimitAreRefusedBeforeAnyWork) {
  const std::string scene = test::source_path("scenes/cornell-box.json");
  const fs::path dir = test::temp_dir("memory-limit-stream");
  ASSERT_EQ(test::run_tracer("bundle " + scene + " -o " + (dir / "c.bundle").string()), 0);
  const std::string runner = fs::path(TRACER_BINARY).parent_path() / "tracer-gpu";
  const std::string wide = " --schedule stream --stream-width 1048576";
  for (const std::string& command :
       {std::string(TRACER_BINARY) + " render " + scene + wide + " --width 1024 --height 1024 -o " +
            (dir / "out.exr").string(),
        runner + " render " + (dir / "c.bundle").string() + " --device cpu" + wide,
        std::string(TRACER_BINARY) + " bench schedule " + scene + " --size 1024 --widths 64,1048576"}) {
    std::string output;
    const int status = run_in_small_cgroup(command, output);
    if (status == 77) GTEST_SKIP() << "no memory cgroup can be made here (needs root and a cgroup mount)";
    EXPECT_EQ(status, 2) << command << "\n" << output;
    EXPECT_NE(output.find("exceed half of the memory cgroup's limit"), std::string::npos) << output;
    EXPECT_EQ(output.find("megakernel"), std::string::npos) << "a row was measured first:\n" << output;
  }
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tracer
