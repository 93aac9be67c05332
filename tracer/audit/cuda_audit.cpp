#include "audit/cuda_audit.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include "io/text_file.h"

namespace fs = std::filesystem;

namespace tracer {

std::vector<std::string> find_cuda_sources(const std::string& root) {
  std::vector<std::string> found;
  const fs::path base(root);
  for (auto it = fs::recursive_directory_iterator(base); it != fs::recursive_directory_iterator(); ++it) {
    const fs::path& p = it->path();
    if (it->is_directory()) {
      if (p.filename().string().front() == '.' || fs::exists(p / "CMakeCache.txt")) it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file() && p.extension() == ".cu") found.push_back(fs::relative(p, base).string());
  }
  std::sort(found.begin(), found.end());
  return found;
}

std::vector<std::string> source_coverage_problems(const std::vector<std::string>& found,
                                                  const std::vector<std::string>& built) {
  const std::set<std::string> f(found.begin(), found.end()), b(built.begin(), built.end());
  std::vector<std::string> problems;
  for (const std::string& s : b)
    if (!f.count(s)) problems.push_back(s + ": the build compiles it but the audit's search did not find it");
  for (const std::string& s : f)
    if (!b.count(s)) problems.push_back(s + ": found in the tree but no CUDA target of the build compiles it");
  return problems;
}

std::vector<std::string> split_build_list(const std::string& list, char separator) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t end = list.find(separator, start);
    const std::string item = list.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!item.empty()) out.push_back(item);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

std::map<std::string, BuiltCudaSource> parse_built_sources(const std::string& list) {
  std::map<std::string, BuiltCudaSource> built;
  for (const std::string& entry : split_build_list(list, ';')) {
    const std::vector<std::string> fields = split_build_list(entry, ':');
    if (fields.size() != 3)
      throw std::invalid_argument("the build's list of CUDA sources: not SOURCE:ARCHS:OBJECT: " + entry);
    built[fields[0]] = {split_build_list(fields[1], ','), fields[2]};
  }
  return built;
}

std::vector<CudaAuditModule> cuda_audit_modules(const std::map<std::string, BuiltCudaSource>& built,
                                                const std::string& build) {
  std::vector<CudaAuditModule> modules;
  for (const auto& [source, b] : built)
    for (const std::string& arch : b.architectures) {
      CudaAuditModule m;
      m.source = source;
      m.architecture = arch;
      m.ptx_path = (fs::path(build) / (b.object + ".compute_" + arch + ".ptx")).string();
      modules.push_back(m);
    }
  return modules;
}

void run_cuda_audit(std::vector<CudaAuditModule>& modules, const std::string& root, int jobs) {
  std::atomic<size_t> next{0};
  std::exception_ptr error;  // the first worker's exception, rethrown after every thread joined
  std::mutex error_mutex;
  const std::string tree = fs::weakly_canonical(root).string();
  const auto work = [&] {
    for (size_t i = next++; i < modules.size(); i = next++) try {
        CudaAuditModule& m = modules[i];
        if (!fs::is_regular_file(m.ptx_path)) {
          m.missing = true;
          continue;
        }
        m.audit = audit_ptx(read_text_file(m.ptx_path, "PTX"), tree);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        next = modules.size();
      }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < std::max(1, jobs); ++t) threads.emplace_back(work);
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace tracer
