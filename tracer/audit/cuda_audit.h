// The instruction audit of a build's CUDA objects: the PTX each .cu file was compiled from, for
// each virtual architecture (kept beside the object by cmake/nvcc_audit_inputs.sh, with
// -lineinfo), goes through audit_ptx (ptx_audit.h); the .cu files of the source tree must be
// those the build compiles.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "audit/ptx_audit.h"

namespace tracer {

// One .cu file as the build compiles it.
struct BuiltCudaSource {
  std::vector<std::string> architectures;  // the virtual architectures of its PTX: "80", "90"
  std::string object;                      // its object, relative to the build directory
};

struct CudaAuditModule {
  std::string source;        // relative to the source tree
  std::string architecture;  // "80"
  std::string ptx_path;
  PtxAudit audit;
  bool missing = false;  // the build kept no PTX at ptx_path
};

// Every .cu file under root (build directories, which hold a CMakeCache.txt, and hidden ones
// skipped), relative to root and sorted.
std::vector<std::string> find_cuda_sources(const std::string& root);

// Differences between the .cu files found and those the build compiles, one line each.
std::vector<std::string> source_coverage_problems(const std::vector<std::string>& found,
                                                  const std::vector<std::string>& built);

// A list the build wrote (generated/cuda_audit_config.h): its items, empty ones dropped.
std::vector<std::string> split_build_list(const std::string& list, char separator);

// The build's list of .cu files, "SOURCE:ARCH,ARCH:OBJECT" entries separated by ';', as a map.
std::map<std::string, BuiltCudaSource> parse_built_sources(const std::string& list);

// The modules the audit reads: each built source's PTX for each of its architectures, beside its
// object in `build` (OBJECT.compute_ARCH.ptx), in the order of the map, not yet read.
std::vector<CudaAuditModule> cuda_audit_modules(const std::map<std::string, BuiltCudaSource>& built,
                                                const std::string& build);

// Reads and audits every module on `jobs` threads (`root`, the source tree, stripped from the
// PTX's file names); a module whose PTX is absent is marked missing.
void run_cuda_audit(std::vector<CudaAuditModule>& modules, const std::string& root, int jobs);

}  // namespace tracer
