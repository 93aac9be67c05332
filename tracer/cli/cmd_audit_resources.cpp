// `tracer audit resources`: every CUDA kernel's registers, stack frame, spills and static
// shared memory on sm_90, from ptxas' report of this build (OBJECT.o.resources beside each CUDA
// object, kept by cmake/nvcc_audit_inputs.sh while the build compiles), against the budgets of
// tracer/audit/kernel_budgets.h, with the occupancy each implies (docs/cuda.md). Exit 0 within
// budget, 1 otherwise, 2 bad input, 77 when this build has no CUDA compiler.
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

#include "audit/cuda_audit.h"
#include "audit/kernel_budgets.h"
#include "audit/kernel_resources.h"
#include "cli/command_registry.h"
#include "cuda_audit_config.h"
#include "io/input_error.h"
#include "io/text_file.h"

namespace fs = std::filesystem;

namespace tracer {
namespace {

int run_audit_resources(const std::string& build_option) {
  if (std::string(TRACER_AUDIT_NVCC).empty()) {
    std::printf("SKIPPED: this build has no CUDA compiler (TRACER_WITH_CUDA=OFF or no nvcc found): no kernels\n");
    return 77;
  }
  const std::string build = build_option.empty() ? TRACER_AUDIT_BUILD_DIR : build_option;
  if (!fs::is_directory(build)) throw InputError(build + ": not a directory (--build)");
  std::vector<KernelResources> kernels;
  size_t reports = 0;
  for (const auto& [source, built] : parse_built_sources(TRACER_AUDIT_CUDA_SOURCES)) {
    const fs::path report = fs::path(build) / (built.object + ".resources");
    if (!fs::is_regular_file(report)) {
      std::printf("FAIL no resource report %s: build with the CUDA launcher, cmake/nvcc_audit_inputs.sh\n",
                  report.string().c_str());
      return 1;
    }
    for (KernelResources& k : parse_resource_report(read_text_file(report.string(), "resource report", 64ull << 20)))
      kernels.push_back(std::move(k));
    ++reports;
  }
  std::map<std::string, const KernelResources*> by_name;  // sm_90 kernels of the tracer, sorted
  for (const KernelResources& k : kernels)
    if (k.arch == "sm_90" && !k.name.empty()) by_name.emplace(k.name, &k);
  std::printf("audit resources: %zu reports under %s; sm_90 kernels of the tracer:\n\n", reports, build.c_str());
  std::printf("%-40s %9s %7s %7s %7s %6s %10s   %s\n", "kernel", "registers", "stack", "spills", "shared", "block",
              "occupancy", "budget (registers, stack, spills, shared)");
  for (const auto& [name, k] : by_name) {
    const KernelBudget* b = find_kernel_budget(name);
    const int block = b ? b->block : 256;
    std::printf("%-40s %9d %7d %7d %7d %6d %9.1f%%   ", name.c_str(), k->registers, k->stack_bytes,
                std::max(k->spill_stores, k->spill_loads), k->shared_bytes, block,
                100.0 * sm90_occupancy(k->registers, block, k->shared_bytes));
    if (b)
      std::printf("%d, %d, %d, %d\n", b->registers, b->stack_bytes, b->spill_bytes, b->shared_bytes);
    else
      std::printf("none\n");
  }
  const std::vector<std::string> problems = budget_problems(kernels);
  for (const std::string& p : problems) std::printf("FAIL %s\n", p.c_str());
  std::printf("\naudit resources: %s (%zu problems)\n", problems.empty() ? "PASS" : "FAIL", problems.size());
  return problems.empty() ? 0 : 1;
}

}  // namespace

const RegisterCommand kAuditResourcesCommand(
    {"audit", "resources",
     "every CUDA kernel's registers, stack and shared memory from ptxas' report, against its budget",
     [](CLI::App& app) {
       auto build = std::make_shared<std::string>();
       app.add_option("--build", *build, "the build tree holding the reports (default: this build's)");
       return [build] { return run_audit_resources(*build); };
     }});

}  // namespace tracer
