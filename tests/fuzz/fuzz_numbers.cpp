// Fuzz target: the command line's number parsers (options/number_text.h) and what is built on
// them: every option of the table as its flag's text, --samples A:B, and the sample lists of the
// benchmarks. The first byte picks the option and a range; the rest is the text. Besides
// "InputError or success", the parsers must keep their promise: an accepted count is digits
// only and at most its maximum, an accepted decimal finite and within its range.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "bench/bench_common.h"
#include "fuzz_sandbox.h"
#include "options/number_text.h"
#include "options/render_options.h"
#include "render/partial_file.h"

namespace {

void require(bool promise, const char* what, const std::string& text) {
  if (promise) return;
  std::fprintf(stderr, "finding: %s for \"%s\"\n", what, text.c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace tracer;
  if (size == 0) return 0;
  const uint8_t pick = data[0];
  const std::string text(reinterpret_cast<const char*>(data + 1), size - 1);

  const uint64_t max = pick < 64 ? (pick == 63 ? UINT64_MAX : (uint64_t{1} << pick)) : 1000u + pick;
  if (const std::optional<uint64_t> count = parse_count(text, max)) {
    require(*count <= max, "a count above its maximum", text);
    require(text.find_first_not_of("0123456789") == std::string::npos, "a count with a non-digit", text);
    const size_t first = std::min(text.find_first_not_of('0'), text.size() - 1);
    require(std::to_string(*count) == text.substr(first), "a count that does not print back as its digits", text);
  }
  const double dmax = static_cast<double>(pick) * 0.5;
  if (const std::optional<double> value = parse_decimal(text, 0.0, dmax))
    require(std::isfinite(*value) && *value >= 0.0 && *value <= dmax, "a decimal outside its range", text);

  const std::vector<OptionInfo>& table = option_table();
  const std::string& name = table[pick % table.size()].name;
  RenderOptions options;
  fuzz::expect_clean_error([&] { parse_option_text(name, text, "fuzz: command line ", options); });

  fuzz::expect_clean_error([&] {
    const SampleRange range = parse_sample_range(text, pick);
    require(range.begin < range.end && range.end <= pick, "a sample range outside [0, spp)", text);
  });
  fuzz::expect_clean_error([&] {
    for (const uint32_t spp : parse_spp_list("--spp", text)) require(spp > 0, "a sample count of 0 in a list", text);
  });
  return 0;
}
