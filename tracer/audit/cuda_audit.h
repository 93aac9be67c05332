// The instruction audit over a source tree: every .cu file under the root is compiled to PTX
// for every architecture the build targets, with the build's own nvcc flags plus -lineinfo,
// and each module goes through audit_ptx (ptx_audit.h).
#pragma once
#include <string>
#include <vector>

#include "audit/ptx_audit.h"

namespace tracer {

struct CudaAuditConfig {
  std::string root;                        // the source tree
  std::string nvcc;                        // the build's nvcc
  std::string flags;                       // the build's nvcc flags, one shell word list
  std::vector<std::string> architectures;  // "80", "90"
  std::vector<std::string> built_sources;  // the .cu files the build compiles, relative to root
  std::string ptx_dir;                     // where nvcc writes the PTX: a directory the audit made
  int jobs = 1;
};

struct CudaAuditModule {
  std::string source;        // relative to root
  std::string architecture;  // "80"
  std::string ptx_path;
  PtxAudit audit;
  std::string compile_error;  // nvcc's output when it failed
};

// Every .cu file under root (build directories, which hold a CMakeCache.txt, and hidden ones
// skipped), relative to root and sorted.
std::vector<std::string> find_cuda_sources(const std::string& root);

// Differences between the .cu files found and those the build compiles, one line each.
std::vector<std::string> source_coverage_problems(const std::vector<std::string>& found,
                                                  const std::vector<std::string>& built);

// Where the PTX of `source` for compute_`arch` goes: the source's own path below ptx_dir, so
// two sources (cuda/a_b.cu, cuda/a/b.cu) never share a file.
std::string ptx_path_for(const std::string& ptx_dir, const std::string& source, const std::string& arch);

std::vector<CudaAuditModule> run_cuda_audit(const CudaAuditConfig& config, const std::vector<std::string>& sources);

}  // namespace tracer
