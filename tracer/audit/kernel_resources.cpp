#include "audit/kernel_resources.h"

#include <cxxabi.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "audit/kernel_budgets.h"

namespace tracer {
namespace {

// The number before `unit` in a line of ptxas' report ("193 registers", "0 bytes spill
// stores"): 0 where the line has no such figure, -1 where its digits do not fit an int (a
// report edited or garbled: 4294967296 registers must not read as 0).
int number_before(const std::string& line, const std::string& unit) {
  const size_t at = line.find(" " + unit);
  if (at == std::string::npos) return 0;
  size_t start = at;
  while (start > 0 && std::isdigit(static_cast<unsigned char>(line[start - 1]))) --start;
  int value = 0;
  const auto [end, error] = std::from_chars(line.data() + start, line.data() + at, value);
  return start == at ? 0 : error == std::errc() && end == line.data() + at ? value : -1;
}

// The text between the first pair of single quotes after `from`.
std::string quoted(const std::string& line, size_t from) {
  const size_t a = line.find('\'', from);
  const size_t b = a == std::string::npos ? a : line.find('\'', a + 1);
  return b == std::string::npos ? "" : line.substr(a + 1, b - a - 1);
}

// Why a kernel's figures cannot be trusted, or "": ptxas printed no "Used" line for it, a
// figure did not fit an int, or its registers exceed what an sm_90 thread can hold.
std::string unreadable(const KernelResources& k) {
  if (!k.used_line) return "has no \"Used ... registers\" line for it";
  for (const auto& [what, value] : {std::pair{"registers", k.registers},
                                    {"stack frame bytes", k.stack_bytes},
                                    {"spill store bytes", k.spill_stores},
                                    {"spill load bytes", k.spill_loads},
                                    {"shared memory bytes", k.shared_bytes}})
    if (value < 0) return std::string("gives a number of ") + what + " that is not a number an int holds";
  if (k.registers > kSm90MaxRegisters)
    return "gives " + std::to_string(k.registers) + " registers, more than an sm_90 thread holds (" +
           std::to_string(kSm90MaxRegisters) + ")";
  return "";
}

}  // namespace

std::vector<KernelResources> parse_resource_report(const std::string& text) {
  std::vector<KernelResources> out;
  std::istringstream in(text);
  std::string line;
  KernelResources* current = nullptr;
  bool properties_of_current = false;
  while (std::getline(in, line)) {
    if (const size_t at = line.find("Compiling entry function "); at != std::string::npos) {
      KernelResources k;
      k.mangled = quoted(line, at);
      const size_t for_at = line.find(" for ", at);
      k.arch = for_at == std::string::npos ? "" : quoted(line, for_at);
      k.name = kernel_name(k.mangled);
      out.push_back(k);
      current = &out.back();
      properties_of_current = false;
    } else if (const size_t props = line.find("Function properties for "); props != std::string::npos) {
      std::string name = line.substr(props + 24);
      while (!name.empty() && (name.back() == ' ' || name.back() == '\r')) name.pop_back();
      properties_of_current = current && name == current->mangled;
    } else if (current && properties_of_current && line.find("bytes stack frame") != std::string::npos) {
      current->stack_bytes = number_before(line, "bytes stack frame");
      current->spill_stores = number_before(line, "bytes spill stores");
      current->spill_loads = number_before(line, "bytes spill loads");
    } else if (current && line.find("ptxas info    : Used ") != std::string::npos) {
      current->registers = number_before(line, "registers");
      current->shared_bytes = number_before(line, "bytes smem");
      current->used_line = true;
      current = nullptr;
    }
  }
  return out;
}

std::string kernel_name(const std::string& mangled) {
  int status = 0;
  const std::unique_ptr<char, void (*)(void*)> d(abi::__cxa_demangle(mangled.c_str(), nullptr, nullptr, &status),
                                                 std::free);
  std::string s = status == 0 && d ? d.get() : mangled;
  if (s.rfind("void ", 0) == 0) s.erase(0, 5);  // a template's return type
  if (s.rfind("tracer::", 0) != 0) return "";
  // Drop the argument list: the first '(' outside template brackets.
  int depth = 0;
  size_t end = s.size(), last_scope = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '<') ++depth;
    if (s[i] == '>') --depth;
    if (depth == 0 && s[i] == '(' && s.compare(i, 21, "(anonymous namespace)") != 0) {
      end = i;
      break;
    }
    if (depth == 0 && s.compare(i, 2, "::") == 0) last_scope = i + 2;
  }
  return s.substr(last_scope, end - last_scope);
}

double sm90_occupancy(int registers, int block, int shared_bytes) {
  if (registers > kSm90MaxRegisters || registers < 0 || block <= 0 || shared_bytes < 0) return 0.0;
  constexpr int64_t kWarps = 64, kBlocks = 32, kRegisters = 65536, kShared = 228 * 1024;
  const int64_t warps_per_block = (int64_t{block} + 31) / 32;
  const int64_t registers_per_warp = (std::max<int64_t>(registers, 1) * 32 + 255) / 256 * 256;
  const int64_t by_registers = kRegisters / registers_per_warp / warps_per_block;
  const int64_t by_warps = kWarps / warps_per_block;
  const int64_t by_shared = kShared / (int64_t{shared_bytes} + 1024);
  const int64_t blocks = std::min({by_registers, by_warps, by_shared, kBlocks});
  return static_cast<double>(blocks * warps_per_block) / kWarps;
}

std::vector<std::string> budget_problems(const std::vector<KernelResources>& kernels) {
  std::vector<std::string> problems;
  std::map<std::string, const KernelResources*> seen;
  std::set<std::string> matched;
  for (const KernelResources& k : kernels) {
    if (k.arch != "sm_90" || k.name.empty()) continue;
    if (const auto it = seen.find(k.name); it != seen.end()) {
      const KernelResources& a = *it->second;
      if (a.registers != k.registers || a.stack_bytes != k.stack_bytes || a.shared_bytes != k.shared_bytes)
        problems.push_back(k.name + ": compiled twice with different resources (" + std::to_string(a.registers) +
                           " and " + std::to_string(k.registers) + " registers)");
      continue;
    }
    seen[k.name] = &k;
    if (const std::string why = unreadable(k); !why.empty()) {
      problems.push_back(k.name + ": ptxas' report " + why);
      if (const KernelBudget* budget = find_kernel_budget(k.name)) matched.insert(budget->kernel);
      continue;
    }
    const KernelBudget* budget = find_kernel_budget(k.name);
    if (!budget) {
      problems.push_back(k.name + ": no row in tracer/audit/kernel_budgets.h; add one (docs/cuda.md)");
      continue;
    }
    matched.insert(budget->kernel);
    const auto over = [&](const char* what, int value, int limit) {
      if (value > limit)
        problems.push_back(k.name + ": " + std::to_string(value) + " " + what + ", over its budget of " +
                           std::to_string(limit));
    };
    over("registers", k.registers, budget->registers);
    over("bytes of stack frame", k.stack_bytes, budget->stack_bytes);
    over("bytes spilled", std::max(k.spill_stores, k.spill_loads), budget->spill_bytes);
    over("bytes of static shared memory", k.shared_bytes, budget->shared_bytes);
  }
  for (const KernelBudget& b : kKernelBudgets)
    if (!matched.count(b.kernel))
      problems.push_back(std::string(b.kernel) + ": a budget row that no sm_90 kernel of the build matches");
  return problems;
}

}  // namespace tracer
