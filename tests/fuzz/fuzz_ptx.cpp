// Fuzz target: PTX text through audit_ptx (audit/ptx_audit.h), the parser behind `tracer audit
// ptx` and `audit cuda`: any text gets counts and parse errors, never a crash (a guard predicate
// with no instruction once read past an empty opcode).
#include <string>

#include "audit/ptx_audit.h"
#include "fuzz_sandbox.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  tracer::fuzz::expect_clean_error([&] {
    const tracer::PtxAudit audit = tracer::audit_ptx(text, "/src");
    if (audit.failures.size() > tracer::kPtxSitesKept || audit.parse_errors.size() > tracer::kPtxSitesKept)
      __builtin_trap();
  });
  return 0;
}
