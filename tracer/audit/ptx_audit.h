// The instruction audit (docs/cuda.md, "The instruction audit"): reads the PTX nvcc emits for
// kernel code and classifies every floating-point and conversion instruction by the source
// line it came from (the innermost `.loc` of -lineinfo):
//   equal      the IEEE 754 operation with round-to-nearest, which the host computes too
//              (add/sub/mul/div/sqrt/rcp .rn, comparisons, sign-bit operations, conversions
//              between float types or from integers with .rn, rounding to an integral float);
//   differs    documented semantics that the host's C++ may not share (min/max: NaN and signed
//              zero; conversions to integers: NaN and out-of-range inputs). Each needs an
//              argument the audit checks itself (see argue_site);
//   forbidden  fma/mad, .approx, .ftz, .sat, .full, directed rounding, a float add/sub/mul
//              without a rounding modifier (ptxas may then contract it), floating-point
//              atomics, a call into libdevice (__nv_*), and any floating-point instruction
//              the table does not know.
#pragma once
#include <map>
#include <string>
#include <vector>

namespace tracer {

enum class PtxClass { Equal, Differs, Forbidden };

struct PtxSite {
  std::string source;    // file:line of the innermost .loc, "unknown" before any
  std::string function;  // the .entry or .func holding it (mangled)
  int ptx_line = 0;
  std::string text;  // the instruction as written
  PtxClass cls = PtxClass::Equal;
  std::string reason;    // why it is forbidden or differs
  std::string argument;  // for an explained "differs" site: the rule that explains it
};

struct PtxCounts {
  long equal = 0, differs = 0, forbidden = 0;
};

// The failures and parse errors kept with their text: what a report can show (a hostile file
// of a million failing lines would otherwise hold a million sites); the rest are counted.
constexpr size_t kPtxSitesKept = 100;

struct PtxAudit {
  std::map<std::string, PtxCounts> by_function;  // mangled .entry/.func name
  std::map<std::string, long> by_opcode;         // e.g. "add.rn.f32", "min.f32"
  std::vector<PtxSite> failures;                 // forbidden, or differs with no argument: the first kPtxSitesKept
  long failure_count = 0;                        // every one
  // differs with an argument, by "file:line  opcode": how many, and the argument
  std::map<std::string, std::pair<long, std::string>> explained;
  std::vector<std::string> parse_errors;  // "LINE: why: text", the first kPtxSitesKept
  long parse_error_count = 0;             // every one
  PtxCounts total() const;
  bool passed() const { return failure_count == 0 && parse_error_count == 0; }
};

// Audits one PTX module. `root` is stripped from the paths of .file entries.
PtxAudit audit_ptx(const std::string& ptx_text, const std::string& root);

// The class of one instruction statement (without its ';') and, unless Equal, the reason.
// Exposed for the unit tests; `source` is the innermost file:line.
PtxSite classify_instruction(const std::string& statement, const std::string& source);

}  // namespace tracer
