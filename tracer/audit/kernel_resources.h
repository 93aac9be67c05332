// What each CUDA kernel holds per thread, from ptxas' own report (nvcc --resource-usage,
// printed while the build compiles each .cu file; cmake/nvcc_audit_inputs.sh keeps it
// beside the object as OBJECT.resources), checked against the budgets of kernel_budgets.h
// (docs/cuda.md, "Resource budgets"). No GPU is needed.
#pragma once
#include <string>
#include <vector>

namespace tracer {

struct KernelResources {
  std::string arch;     // "sm_90"
  std::string name;     // kernel_name(mangled)
  std::string mangled;  // as ptxas prints it
  int registers = 0;
  int stack_bytes = 0;  // the stack frame: local arrays, spills and calls
  int spill_stores = 0, spill_loads = 0;
  int shared_bytes = 0;    // static shared memory
  bool used_line = false;  // ptxas printed its "Used N registers" line (else nothing above is known)
};

// The most registers a thread of compute capability 9.0 holds.
inline constexpr int kSm90MaxRegisters = 255;

// The kernels of one report, in the order ptxas compiled them.
std::vector<KernelResources> parse_resource_report(const std::string& text);

// A kernel's readable name: namespaces and arguments dropped, template arguments kept
// ("render_kernel", "stage_kernel<(tracer::StreamStage)1>"); "" for a kernel outside the
// tracer's namespace (a library's, such as CUB's sort).
std::string kernel_name(const std::string& mangled);

// The fraction of an sm_90 multiprocessor's 64 warps that blocks of `block` threads keep
// resident, given each thread's registers and each block's static shared memory (the CUDA
// occupancy calculator's rules for compute capability 9.0: 65,536 registers allocated 256 per
// warp, 32 blocks, 228 KiB of shared memory with 1 KiB reserved per block); 0 for figures no
// sm_90 kernel can have (over 255 registers, negative).
double sm90_occupancy(int registers, int block, int shared_bytes);

struct KernelBudget;
// Every problem with the sm_90 kernels against the budgets, one line each: a kernel over a
// budget, a kernel of the tracer without a row, a row no kernel matches, one kernel compiled
// twice with different resources, a kernel whose report cannot be read (no "Used" line, a
// figure past int's range or past 255 registers).
std::vector<std::string> budget_problems(const std::vector<KernelResources>& kernels);

}  // namespace tracer
