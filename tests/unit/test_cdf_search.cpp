// find_cdf_interval, the discrete draw behind light choice and sky cells: the first entry
// whose cdf exceeds u, checked against a linear scan on distributions with zero-probability
// runs, u at, just below and just above every cdf value, and a last cdf that rounding left
// below 1.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kernel/shading/sampling.h"

using namespace tracer;

namespace {

struct CdfEntry {
  float cdf;
};

uint32_t linear_scan(const std::vector<CdfEntry>& entries, float u) {
  for (uint32_t i = 0; i < entries.size(); ++i)
    if (u < entries[i].cdf) return i;
  return static_cast<uint32_t>(entries.size()) - 1u;
}

}  // namespace

TEST(CdfSearch, FindsTheFirstEntryAboveUOnEveryDistribution) {
  uint32_t state = 12345u;
  const auto next = [&state] { return state = state * 1664525u + 1013904223u; };
  for (uint32_t count = 1; count <= 40; ++count)
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<CdfEntry> entries(count);
      float sum = 0.0f;
      for (auto& e : entries) {
        sum += next() % 3 == 0 ? 0.0f : static_cast<float>(next() % 16 + 1);  // runs of zero pmf
        e.cdf = sum;
      }
      for (auto& e : entries) e.cdf = sum > 0.0f ? e.cdf / sum : 1.0f;
      if (trial % 5 == 0) entries.back().cdf = 0x1.fffffcp-1f;  // rounding left the total below 1
      std::vector<float> us = {0.0f, 0x1.fffffep-1f, 0.5f};
      for (const auto& e : entries)
        for (float u : {std::nextafter(e.cdf, 0.0f), e.cdf, std::nextafter(e.cdf, 1.0f)})
          if (u >= 0.0f && u < 1.0f) us.push_back(u);
      for (float u : us)
        ASSERT_EQ(find_cdf_interval(entries.data(), count, u), linear_scan(entries, u))
            << "count " << count << " trial " << trial << " u " << u;
    }
}
