#pragma once
// Wall-clock timing for the studies: elapsed seconds, and medians of repeated runs (these
// machines are shared and noisy; a median of a few runs is what the studies report).
#include <algorithm>
#include <chrono>
#include <vector>

namespace thinlayer {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The median (mean of the two middle values for an even count); 0 for no values.
inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The median wall time of `repeats` calls of f (at least one call).
template <class F>
double median_time(int repeats, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < std::max(1, repeats); ++i) {
    const auto start = Clock::now();
    f();
    t.push_back(seconds_since(start));
  }
  return median(t);
}

}  // namespace thinlayer
