// Numbers as the command line accepts them. A count is decimal digits only: no sign, space,
// hex, exponent or empty string, and no value above `max` (checked without overflow). A
// threshold is plain decimal notation, digits with at most one point, finite, within [min, max].
// Both give nullopt for anything else; the callers name the flag in their errors.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tracer {

std::optional<uint64_t> parse_count(std::string_view text, uint64_t max);
std::optional<double> parse_decimal(std::string_view text, double min, double max);

std::string count_range(uint64_t min, uint64_t max);  // "a whole number from MIN to MAX"

// The double nearest the shortest decimal that reads back as `value`: a float threshold of
// 0.2 is written to JSON as 0.2, not as its exact 0.20000000298023224.
double shortest_decimal(float value);

}  // namespace tracer
