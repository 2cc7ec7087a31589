#pragma once
#include <algorithm>
#include <vector>

namespace throng::tools {
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// The median and the extremes of a series (per-pair ratios of two things measured in turn);
// zeros when it is empty.
struct Spread {
  double median = 0.0, min = 0.0, max = 0.0;
};
inline Spread spreadOf(const std::vector<double>& values) {
  if (values.empty()) return {};
  const auto [lowest, highest] = std::minmax_element(values.begin(), values.end());
  return {tools::median(values), *lowest, *highest};
}

// Two things measured in turn, so that both see the same moments of the machine's load: the
// times of each and, per pair, the second's over the first's.
struct InTurn {
  std::vector<double> first, second, ratios;
  void add(double a, double b) {
    first.push_back(a);
    second.push_back(b);
    ratios.push_back(b / a);
  }
  int pairs() const { return int(ratios.size()); }
};
}  // namespace throng::tools
