// `tracer audit cuda`: the instruction audit of the CUDA kernels (docs/cuda.md), with the nvcc,
// flags, architectures and .cu files of this build (generated/cuda_audit_config.h);
// `tracer audit ptx FILE...` audits PTX files as they are; `tracer audit draws`: the lint for
// two draws from one stream in one argument list. Exit 0 clean, 1 findings, 2 bad input,
// 77 no nvcc in this build (CTest reports the test skipped, with the reason).
#include <cxxabi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <system_error>
#include <thread>

#include "audit/cuda_audit.h"
#include "audit/draw_lint.h"
#include "audit/ptx_directory.h"
#include "cli/command_registry.h"
#include "cuda_audit_config.h"
#include "io/input_error.h"
#include "io/text_file.h"

namespace fs = std::filesystem;

namespace tracer {
namespace {

std::string demangled(const std::string& name) {
  int status = 0;
  std::unique_ptr<char, void (*)(void*)> d(abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status), std::free);
  if (status != 0 || !d) return name;
  std::string s = d.get();
  for (const std::string noise : {"tracer::", "(anonymous namespace)::", "void "})
    for (size_t at; (at = s.find(noise)) != std::string::npos;) s.erase(at, noise.size());
  s = s.substr(0, s.find_first_of("(<"));
  // A library's kernel (thrust's sort is CUB's): the library and the kernel's own name.
  const size_t last = s.rfind("::");
  if (s.rfind("cub::", 0) == 0 || s.rfind("thrust::", 0) == 0) s = s.substr(0, s.find("::")) + " " + s.substr(last + 2);
  return s;
}

const char* class_name(PtxClass c) {
  return c == PtxClass::Equal ? "equal" : c == PtxClass::Differs ? "differs" : "forbidden";
}

// Prints the tables and the findings; returns the number of failures.
size_t report(const std::vector<CudaAuditModule>& modules) {
  size_t failures = 0;
  std::printf("%-28s %-5s %-36s %8s %8s %10s\n", "source", "arch", "kernel or device function", "equal", "differs",
              "forbidden");
  std::map<std::string, std::map<std::string, long>> opcodes;     // arch -> opcode -> count
  std::map<std::string, std::pair<long, std::string>> arguments;  // "file:line opcode" -> count, argument
  for (const CudaAuditModule& m : modules) {
    if (!m.compile_error.empty()) {
      std::printf("%-28s %-5s nvcc failed:\n%s\n", m.source.c_str(), m.architecture.c_str(), m.compile_error.c_str());
      ++failures;
      continue;
    }
    if (m.audit.by_function.empty())
      std::printf("%-28s %-5s %-36s\n", m.source.c_str(), m.architecture.c_str(), "(no device code)");
    for (const auto& [fn, c] : m.audit.by_function)
      std::printf("%-28s %-5s %-36s %8ld %8ld %10ld\n", m.source.c_str(), m.architecture.c_str(),
                  demangled(fn).substr(0, 36).c_str(), c.equal, c.differs, c.forbidden);
    for (const auto& [op, n] : m.audit.by_opcode) opcodes[m.architecture][op] += n;
    for (const auto& [site, entry] : m.audit.explained) {
      auto& [count, argument] = arguments[site];
      count += entry.first;
      argument = entry.second;
    }
  }
  std::printf("\ninstructions by opcode (all modules)\n");
  for (const auto& [arch, ops] : opcodes) {
    std::printf("compute_%s:", arch.c_str());
    for (const auto& [op, n] : ops) {
      const PtxClass c = classify_instruction(op + " %x", "").cls;
      std::printf(" %s %ld (%s);", op.c_str(), n, class_name(c));
    }
    std::printf("\n");
  }
  std::printf("\n\"differs\" sites with their argument (all modules and architectures)\n");
  for (const auto& [site, entry] : arguments)
    std::printf("  %-58s x%-5ld %s\n", site.c_str(), entry.first, entry.second.c_str());
  for (const CudaAuditModule& m : modules) {
    for (const std::string& e : m.audit.parse_errors) {
      std::printf("FAIL %s (%s): PTX the audit cannot parse, line %s\n", m.source.c_str(), m.ptx_path.c_str(),
                  e.c_str());
    }
    for (const PtxSite& s : m.audit.failures) {
      std::printf("FAIL %s: %s `%s` (%s, compute_%s, PTX line %d, in %s): %s%s\n", s.source.c_str(), class_name(s.cls),
                  s.text.c_str(), m.source.c_str(), m.architecture.c_str(), s.ptx_line, demangled(s.function).c_str(),
                  s.reason.c_str(), s.cls == PtxClass::Differs ? "; no argument the audit accepts (docs/cuda.md)" : "");
    }
    const long unshown = m.audit.failure_count + m.audit.parse_error_count -
                         static_cast<long>(m.audit.failures.size() + m.audit.parse_errors.size());
    if (unshown > 0) std::printf("FAIL %s: %ld more failures, not shown\n", m.source.c_str(), unshown);
    failures += static_cast<size_t>(m.audit.failure_count + m.audit.parse_error_count);
  }
  return failures;
}

// nvcc failing (a source that does not compile, a full disk, a crash) is no verdict on the
// instructions: the audit exits 2 and leaves an earlier PTX directory as it was.
std::string nvcc_failure_text(const std::vector<CudaAuditModule>& modules, const CudaAuditModule& first,
                              const PtxDirectory& ptx) {
  const long failed =
      std::count_if(modules.begin(), modules.end(), [](const CudaAuditModule& m) { return !m.compile_error.empty(); });
  std::string text = "audit cuda: nvcc failed on " + std::to_string(failed) + " of " + std::to_string(modules.size()) +
                     " modules (the first: " + first.source + " for compute_" + first.architecture +
                     "; nvcc's output is above), so the audit gives no verdict; " + ptx.path() +
                     " (--ptx-dir) is left as it was";
  std::error_code ec;
  const fs::space_info space = fs::space(ptx.staging(), ec);
  constexpr uintmax_t kLowSpace = 64ull << 20;  // ten times the largest module's PTX
  if (!ec && space.available < kLowSpace)
    text += "; the disk holding it has " + std::to_string(space.available >> 10) + " KiB free";
  return text;
}

int run_audit_cuda(const std::string& root_option, const std::string& ptx_dir_option) {
  const std::string root = root_option.empty() ? TRACER_AUDIT_SOURCE_DIR : root_option;
  if (!fs::is_directory(root)) throw InputError(root + ": not a directory (--root)");
  if (std::string(TRACER_AUDIT_NVCC).empty()) {
    std::printf(
        "SKIPPED: this build has no CUDA compiler (TRACER_WITH_CUDA=OFF or no nvcc found); the audit reads "
        "nvcc's PTX and needs it\n");
    return 77;
  }
  CudaAuditConfig config;
  config.root = root;
  config.nvcc = TRACER_AUDIT_NVCC;
  config.flags = TRACER_AUDIT_CUDA_FLAGS;
  config.architectures = split_build_list(TRACER_AUDIT_CUDA_ARCHITECTURES, ';');
  config.built_sources = parse_built_sources(TRACER_AUDIT_CUDA_SOURCES);
  PtxDirectory ptx(ptx_dir_option.empty() ? TRACER_AUDIT_PTX_DIR : ptx_dir_option, ptx_dir_option.empty());
  config.ptx_dir = ptx.staging();
  config.jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const std::vector<std::string> sources = find_cuda_sources(root);
  std::printf("audit cuda: %s, flags: %s\narchitectures:", config.nvcc.c_str(), config.flags.c_str());
  for (const std::string& a : config.architectures) std::printf(" compute_%s", a.c_str());
  std::printf("\nsources (%zu found under %s), each for the architectures the build compiles its PTX for:",
              sources.size(), root.c_str());
  for (const std::string& s : sources) {
    std::printf(" %s", s.c_str());
    const auto built = config.built_sources.find(s);
    if (built != config.built_sources.end())
      for (size_t i = 0; i < built->second.size(); ++i)
        std::printf("%c%s", i == 0 ? ':' : ',', built->second[i].c_str());
  }
  std::printf("\nPTX kept in %s\n\n", ptx.path().c_str());
  size_t failures = 0;
  std::vector<std::string> built;
  for (const auto& [source, architectures] : config.built_sources) built.push_back(source);
  for (const std::string& p : source_coverage_problems(sources, built)) {
    std::printf("FAIL %s\n", p.c_str());
    ++failures;
  }
  if (sources.empty()) {
    std::printf("FAIL no .cu file under %s\n", root.c_str());
    ++failures;
  }
  std::vector<CudaAuditModule> modules = run_cuda_audit(config, sources);
  const auto unbuilt =
      std::find_if(modules.begin(), modules.end(), [](const CudaAuditModule& m) { return !m.compile_error.empty(); });
  if (unbuilt != modules.end()) {
    report(modules);  // nvcc's output for each module it failed on
    throw InputError(nvcc_failure_text(modules, *unbuilt, ptx));
  }
  ptx.keep();
  for (CudaAuditModule& m : modules) m.ptx_path = ptx.path() + m.ptx_path.substr(ptx.staging().size());
  failures += report(modules);
  std::printf("\naudit cuda: %s (%zu failures)\n", failures == 0 ? "PASS" : "FAIL", failures);
  return failures == 0 ? 0 : 1;
}

// The largest PTX file `audit ptx` reads: 32x the largest module of this tree (gpu_stream.cu, 6 MB),
// which the audit holds about three times over.
constexpr uint64_t kPtxFileMaxBytes = 192ull << 20;

int run_audit_ptx(const std::vector<std::string>& files, const std::string& root) {
  std::vector<CudaAuditModule> modules;
  for (const std::string& f : files) {
    CudaAuditModule m;
    m.source = f;
    m.architecture = "-";
    m.ptx_path = f;
    m.audit = audit_ptx(read_text_file(f, "PTX file", kPtxFileMaxBytes), root);
    modules.push_back(m);
  }
  const size_t failures = report(modules);
  std::printf("\naudit ptx: %s (%zu failures)\n", failures == 0 ? "PASS" : "FAIL", failures);
  return failures == 0 ? 0 : 1;
}

int run_audit_draws(const std::string& root_option) {
  const std::string root = root_option.empty() ? TRACER_AUDIT_SOURCE_DIR : root_option;
  if (!fs::is_directory(root)) throw InputError(root + ": not a directory (--root)");
  const std::vector<DrawLintFinding> findings = lint_draws_in_tree(root);
  for (const DrawLintFinding& f : findings)
    std::printf(
        "FAIL %s:%d: %d draws from one stream in one argument list; C++ leaves their order unspecified, so "
        "compilers feed different values: draw them in separate statements\n",
        f.file.c_str(), f.line, f.draws);
  std::printf("audit draws: %s (%zu findings in tracer/kernel, cuda and tests)\n", findings.empty() ? "PASS" : "FAIL",
              findings.size());
  return findings.empty() ? 0 : 1;
}

}  // namespace

const RegisterCommand kAuditCudaCommand(
    {"audit", "cuda", "compile every .cu to PTX with this build's flags and classify every floating-point instruction",
     [](CLI::App& app) {
       auto root = std::make_shared<std::string>();
       auto ptx_dir = std::make_shared<std::string>();
       app.add_option("--root", *root, "source tree (default: the one this build was configured from)");
       app.add_option("--ptx-dir", *ptx_dir,
                      "where the PTX is kept: a new path or an earlier audit's directory, which it replaces "
                      "(default: BUILD/ptx-audit)");
       return [root, ptx_dir] { return run_audit_cuda(*root, *ptx_dir); };
     }});

const RegisterCommand kAuditPtxCommand(
    {"audit", "ptx", "classify every floating-point instruction of PTX files", [](CLI::App& app) {
       auto files = std::make_shared<std::vector<std::string>>();
       auto root = std::make_shared<std::string>();
       app.add_option("files", *files, "PTX files (nvcc -ptx -lineinfo)")->required();
       app.add_option("--root", *root, "prefix stripped from source paths");
       return [files, root] { return run_audit_ptx(*files, *root); };
     }});

const RegisterCommand kAuditDrawsCommand(
    {"audit", "draws", "find two draws from one input stream in one argument list (kernel, cuda and test code)",
     [](CLI::App& app) {
       auto root = std::make_shared<std::string>();
       app.add_option("--root", *root, "source tree (default: the one this build was configured from)");
       return [root] { return run_audit_draws(*root); };
     }});

}  // namespace tracer
