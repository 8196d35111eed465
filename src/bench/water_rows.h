// What the water benchmarks (bench fluid, bench balls) add to a scene for their rows: force probes
// (what measuring the loads costs) and floating boxes (what bodies cost), and the lists that
// choose them.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "sim/water/setup.h"

namespace tidepool::bench {

// A comma list of whole numbers in [lo, hi] for `option` ("--iterations 2,4,8"); throws Error.
std::vector<int> parseWholeNumbers(const std::string& text, const char* option, long lo, long hi);

// The scene's probes, and with `loads` a force probe on the floor and on each obstacle.
std::vector<water::ProbeParams> loadProbes(const water::Setup& s, bool loads);

// `n` boxes of 500 kg/m³ at the fill's top, in two rows across it, a tenth of its width wide,
// added to the scene's obstacles: dynamic, or held where they are. Throws Error past kMaxObstacles.
void addFloatingBoxes(water::Setup& s, int n, bool dynamic);

// The rows of --bodies and --dynamic: each body count with each setting (none: one row), as
// (count, dynamic).
std::vector<std::pair<int, bool>> bodyRows(const std::string& bodies, const std::string& dynamic);

}  // namespace tidepool::bench
