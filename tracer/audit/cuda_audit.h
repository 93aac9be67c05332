// The instruction audit over a source tree: every .cu file under the root is compiled to PTX
// for each architecture the build compiles its PTX for, with the build's own nvcc flags plus
// -lineinfo, and each module goes through audit_ptx (ptx_audit.h).
#pragma once
#include <map>
#include <string>
#include <vector>

#include "audit/ptx_audit.h"

namespace tracer {

struct CudaAuditConfig {
  std::string root;                        // the source tree
  std::string nvcc;                        // the build's nvcc
  std::string flags;                       // the build's nvcc flags, one shell word list
  std::vector<std::string> architectures;  // every PTX architecture of the build: "80", "90"
  // the .cu files the build compiles, relative to root, each with the architectures nvcc
  // compiles its PTX for (a file the build does not compile is audited for every one)
  std::map<std::string, std::vector<std::string>> built_sources;
  std::string ptx_dir;  // where nvcc writes the PTX: a directory the audit made
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

// A list the build wrote (generated/cuda_audit_config.h): its items, empty ones dropped.
std::vector<std::string> split_build_list(const std::string& list, char separator);

// The build's list of .cu files, "SOURCE:ARCH,ARCH" entries separated by ';', as a map.
std::map<std::string, std::vector<std::string>> parse_built_sources(const std::string& list);

// Where the PTX of `source` for compute_`arch` goes: the source's own path below ptx_dir, so
// two sources (cuda/a_b.cu, cuda/a/b.cu) never share a file.
std::string ptx_path_for(const std::string& ptx_dir, const std::string& source, const std::string& arch);

// The modules the audit compiles: each source for its built architectures, in order, not yet compiled.
std::vector<CudaAuditModule> cuda_audit_modules(const CudaAuditConfig& config, const std::vector<std::string>& sources);

std::vector<CudaAuditModule> run_cuda_audit(const CudaAuditConfig& config, const std::vector<std::string>& sources);

}  // namespace tracer
