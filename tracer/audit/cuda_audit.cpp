#include "audit/cuda_audit.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include "io/shell.h"
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

std::map<std::string, std::vector<std::string>> parse_built_sources(const std::string& list) {
  std::map<std::string, std::vector<std::string>> built;
  for (const std::string& entry : split_build_list(list, ';')) {
    const size_t colon = entry.rfind(':');
    if (colon == std::string::npos)
      throw std::invalid_argument("the build's source list: no architectures in " + entry);
    built[entry.substr(0, colon)] = split_build_list(entry.substr(colon + 1), ',');
  }
  return built;
}

std::string ptx_path_for(const std::string& ptx_dir, const std::string& source, const std::string& arch) {
  return (fs::path(ptx_dir) / (source + ".compute_" + arch + ".ptx")).string();
}

std::vector<CudaAuditModule> cuda_audit_modules(const CudaAuditConfig& config,
                                                const std::vector<std::string>& sources) {
  std::vector<CudaAuditModule> modules;
  for (const std::string& source : sources) {
    const auto built = config.built_sources.find(source);
    for (const std::string& arch : built != config.built_sources.end() ? built->second : config.architectures) {
      CudaAuditModule m;
      m.source = source;
      m.architecture = arch;
      m.ptx_path = ptx_path_for(config.ptx_dir, source, arch);
      modules.push_back(m);
    }
  }
  return modules;
}

std::vector<CudaAuditModule> run_cuda_audit(const CudaAuditConfig& config, const std::vector<std::string>& sources) {
  std::vector<CudaAuditModule> modules = cuda_audit_modules(config, sources);
  for (const CudaAuditModule& m : modules) fs::create_directories(fs::path(m.ptx_path).parent_path());
  std::atomic<size_t> next{0};
  std::exception_ptr error;  // the first worker's exception, rethrown after every thread joined
  std::mutex error_mutex;
  const auto work = [&] {
    for (size_t i = next++; i < modules.size(); i = next++) try {
        CudaAuditModule& m = modules[i];
        const fs::path root = fs::weakly_canonical(config.root);
        const std::string command =
            shell_quote(config.nvcc) + " -ptx -lineinfo -arch=compute_" + m.architecture + " " + config.flags + " -I" +
            shell_quote((root / "tracer").string()) + " -I" + shell_quote((root / "cuda").string()) + " " +
            shell_quote((root / m.source).string()) + " -o " + shell_quote(m.ptx_path) + " 2>&1";
        std::string output;
        if (run_capture(command, output) != 0) {
          m.compile_error = command + "\n" + output;
          continue;
        }
        m.audit = audit_ptx(read_text_file(m.ptx_path, "PTX"), root.string());
      } catch (...) {
        const std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
        next = modules.size();
      }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < std::max(1, config.jobs); ++t) threads.emplace_back(work);
  for (std::thread& t : threads) t.join();
  if (error) std::rethrow_exception(error);
  return modules;
}

}  // namespace tracer
