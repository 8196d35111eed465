// Watching a simulation for divergence without stalling the GPU. A model reduces its state to a
// few numbers on the GPU every few frames (NaN count, largest magnitudes) and hands them here
// through an AsyncReadback; when they arrive one to two frames later they are judged. Healthy
// results promote the state copied at that same moment to "last good state", so a blow-up can
// be undone exactly.
#pragma once

#include <optional>
#include <string>

namespace tidepool {

struct Health {
  double time = 0;          // simulated seconds at the check
  double nanCount = 0;      // non-finite values in the state
  double maxMagnitude = 0;  // largest |value| of the watched quantity
};

struct DivergenceReport {
  std::string message;  // what failed, with method and time step, and what to do
  double time = 0;      // simulated seconds of the failed check
};

}  // namespace tidepool
