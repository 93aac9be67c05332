// The memory this process may use: the machine's physical memory, or the limit of the memory
// cgroup it runs in when that is lower (Slurm's --mem, a container's limit). Linux lends memory
// it may not have and kills the process when it is touched, so a command that allocates a
// large block at once compares it with this first. The cgroup is the one /proc/self/cgroup
// names: cgroup v2's memory.max (the unified hierarchy) or v1's memory.limit_in_bytes, the
// lowest of the cgroup and each parent that the mount shows. Header-only: the GPU runner uses
// it too.
#pragma once
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace tracer {

struct MemoryLimit {
  uint64_t bytes = 0;  // 0: unknown
  std::string source;  // "this machine's memory" or "the memory cgroup's limit (FILE)"
};

namespace memory_limit_detail {

// The lowest limit in FILE_NAME of the cgroup at `path` below `mount` and of its parents.
inline void lower_by_cgroup(MemoryLimit& limit, const std::string& mount, std::string path, const char* file_name) {
  while (true) {
    const std::string file = mount + (path == "/" ? "" : path) + "/" + file_name;
    std::ifstream in(file);
    std::string text;
    if (in >> text && text != "max") {
      char* end = nullptr;
      const unsigned long long bytes = std::strtoull(text.c_str(), &end, 10);
      if (end && *end == '\0' && bytes > 0 && bytes < limit.bytes)
        limit = {bytes, "the memory cgroup's limit (" + file + ")"};
    }
    if (path.empty() || path == "/") return;
    const size_t slash = path.rfind('/');
    path = slash == 0 ? "/" : path.substr(0, slash);
  }
}

}  // namespace memory_limit_detail

// `proc_cgroup` and `cgroup_mount` are /proc/self/cgroup and /sys/fs/cgroup but for tests.
inline MemoryLimit memory_limit(const std::string& proc_cgroup = "/proc/self/cgroup",
                                const std::string& cgroup_mount = "/sys/fs/cgroup") {
  MemoryLimit limit;
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
  if (pages > 0 && page_size > 0)
    limit = {static_cast<uint64_t>(pages) * static_cast<uint64_t>(page_size), "this machine's memory"};
  else
    limit.bytes = UINT64_MAX;
  std::ifstream in(proc_cgroup);
  for (std::string line; std::getline(in, line);) {  // "ID:CONTROLLERS:PATH"
    const size_t a = line.find(':'), b = a == std::string::npos ? a : line.find(':', a + 1);
    if (b == std::string::npos) continue;
    const std::string controllers = line.substr(a + 1, b - a - 1), path = line.substr(b + 1);
    if (line.compare(0, a, "0") == 0 && controllers.empty()) {  // v2, alone or beside v1 ("unified")
      memory_limit_detail::lower_by_cgroup(limit, cgroup_mount, path, "memory.max");
      memory_limit_detail::lower_by_cgroup(limit, cgroup_mount + "/unified", path, "memory.max");
    }
    std::stringstream names(controllers);
    for (std::string name; std::getline(names, name, ',');)
      if (name == "memory")
        memory_limit_detail::lower_by_cgroup(limit, cgroup_mount + "/memory", path, "memory.limit_in_bytes");
  }
  if (limit.bytes == UINT64_MAX) limit.bytes = 0;
  return limit;
}

}  // namespace tracer
