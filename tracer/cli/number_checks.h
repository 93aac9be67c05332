// CLI11 checks holding command-line numbers to the rules of options/number_text.h. CLI11 runs
// them on the text before converting it; alone it accepts " 4", "0x10" and "" as counts and
// nan, -1 or 1e999 as thresholds.
#pragma once
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "options/number_text.h"

namespace tracer {

inline CLI::Validator count_in(uint64_t min, uint64_t max) {
  const std::string range = count_range(min, max);
  return CLI::Validator(
      [=](std::string& text) {
        const std::optional<uint64_t> value = parse_count(text, max);
        return value && *value >= min ? std::string() : "\"" + text + "\": expected " + range;
      },
      "COUNT in [" + std::to_string(min) + ", " + std::to_string(max) + "]");
}

inline CLI::Validator decimal_in(double min, double max) {
  const std::string range = "a decimal number (digits and at most one point) from " + CLI::detail::to_string(min) +
                            " to " + CLI::detail::to_string(max);
  return CLI::Validator(
      [=](std::string& text) {
        return parse_decimal(text, min, max) ? std::string() : "\"" + text + "\": expected " + range;
      },
      "NUMBER in [" + CLI::detail::to_string(min) + ", " + CLI::detail::to_string(max) + "]");
}

}  // namespace tracer
