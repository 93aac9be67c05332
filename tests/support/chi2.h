// The chi-square goodness-of-fit statistic of the sampling tests: bins expecting fewer than
// 5 samples are pooled, and the p-value comes from the regularised upper incomplete gamma
// function.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

namespace tracer::test {

// Regularised upper incomplete gamma Q(a, x): series below a + 1, continued fraction above.
inline double gamma_q(double a, double x) {
  if (x <= 0) return 1.0;
  const double log_prefix = a * std::log(x) - x - std::lgamma(a);
  if (x < a + 1) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 10000 && term > sum * 1e-15; ++n) sum += term *= x / (a + n);
    return 1.0 - sum * std::exp(log_prefix);
  }
  double b = x + 1 - a, c = 1e300, d = 1 / b, h = d;  // modified Lentz
  for (int i = 1; i < 10000; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    c = b + an / c;
    d = 1 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1) < 1e-15) break;
  }
  return std::exp(log_prefix) * h;
}

// Pools bins expecting fewer than 5 samples, then returns the chi-square p-value.
inline double chi2_p_value(const std::vector<double>& observed, const std::vector<double>& expected) {
  double chi2 = 0, pooled_o = 0, pooled_e = 0;
  int cells = 0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] < 5) {
      pooled_o += observed[i], pooled_e += expected[i];
      continue;
    }
    chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++cells;
  }
  if (pooled_e > 0) chi2 += (pooled_o - pooled_e) * (pooled_o - pooled_e) / std::max(pooled_e, 1e-12), ++cells;
  return gamma_q((cells - 1) / 2.0, chi2 / 2.0);
}

}  // namespace tracer::test
