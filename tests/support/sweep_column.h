// The tests of the sweep studies read a row's metric by its CSV column name.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "sweep/sweep.h"

namespace tidepool::test {

// The index in Row::metrics of the metric named `metric` (a failure, and 0, when there is none).
inline std::size_t metricColumn(const sweep::Result& r, const std::string& metric) {
  for (std::size_t i = 0; i < r.metrics.size(); ++i)
    if (r.metrics[i] == metric) return i;
  ADD_FAILURE() << "no metric " << metric;
  return 0;
}

}  // namespace tidepool::test
