// Bisection for stability limits: the largest x in [stable, unstable] with isStable(x).
#pragma once

#include <functional>

namespace tidepool {

// Assumes isStable(stable) and !isStable(unstable); stops at a relative width of `tolerance`.
inline double bisectLimit(double stable, double unstable, double tolerance,
                          const std::function<bool(double)>& isStable) {
  while ((unstable - stable) / stable > tolerance) {
    const double mid = 0.5 * (stable + unstable);
    (isStable(mid) ? stable : unstable) = mid;
  }
  return 0.5 * (stable + unstable);
}

// The largest stable x in [smallest, largest] by bisectLimit, or 0 when even `smallest` fails
// (a method unstable at every step tried, e.g. explicit Euler on an undamped oscillator).
inline double largestStable(double smallest, double largest, double tolerance,
                            const std::function<bool(double)>& isStable) {
  return isStable(smallest) ? bisectLimit(smallest, largest, tolerance, isStable) : 0.0;
}

}  // namespace tidepool
