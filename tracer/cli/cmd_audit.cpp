// `tracer audit cuda`: the instruction audit of the CUDA kernels (docs/cuda.md): the PTX this
// build compiled each CUDA object from, kept beside it (generated/cuda_audit_config.h lists them);
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
    if (m.missing) {
      std::printf(
          "FAIL %s: no PTX at %s: build the CUDA objects with this build's launcher, "
          "cmake/nvcc_audit_inputs.sh (cmake --build BUILD)\n",
          m.source.c_str(), m.ptx_path.c_str());
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

int run_audit_cuda(const std::string& build_option) {
  if (std::string(TRACER_AUDIT_NVCC).empty()) {
    std::printf(
        "SKIPPED: this build has no CUDA compiler (TRACER_WITH_CUDA=OFF or no nvcc found); the audit reads "
        "nvcc's PTX and needs it\n");
    return 77;
  }
  const std::string build = build_option.empty() ? TRACER_AUDIT_BUILD_DIR : build_option;
  if (!fs::is_directory(build)) throw InputError(build + ": not a directory (--build)");
  const std::string root = TRACER_AUDIT_SOURCE_DIR;
  const std::map<std::string, BuiltCudaSource> built = parse_built_sources(TRACER_AUDIT_CUDA_SOURCES);
  const std::vector<std::string> sources = find_cuda_sources(root);
  std::printf("audit cuda: the PTX %s compiled each CUDA object of %s from (-lineinfo)\nsources (%zu found under %s):",
              TRACER_AUDIT_NVCC, build.c_str(), sources.size(), root.c_str());
  for (const std::string& s : sources) {
    std::printf(" %s", s.c_str());
    const auto b = built.find(s);
    if (b != built.end())
      for (size_t i = 0; i < b->second.architectures.size(); ++i)
        std::printf("%c%s", i == 0 ? ':' : ',', b->second.architectures[i].c_str());
  }
  std::printf("\n\n");
  size_t failures = 0;
  std::vector<std::string> built_names;
  for (const auto& [source, b] : built) built_names.push_back(source);
  for (const std::string& p : source_coverage_problems(sources, built_names)) {
    std::printf("FAIL %s\n", p.c_str());
    ++failures;
  }
  if (sources.empty()) {
    std::printf("FAIL no .cu file under %s\n", root.c_str());
    ++failures;
  }
  std::vector<CudaAuditModule> modules = cuda_audit_modules(built, build);
  run_cuda_audit(modules, root, static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
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
    {"audit", "cuda", "classify every floating-point instruction of the PTX this build compiled its CUDA objects from",
     [](CLI::App& app) {
       auto build = std::make_shared<std::string>();
       app.add_option("--build", *build, "the build tree holding the objects' PTX (default: this build's)");
       return [build] { return run_audit_cuda(*build); };
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
