// The table of benchmarks `tidepool bench` offers. Each benchmark adds one line when it lands.
#include "bench/bench.h"

namespace tidepool::bench {

Benchmark addRipplesBench(CLI::App& bench);

const std::vector<Registrar>& registrars() {
  static const std::vector<Registrar> table = {addRipplesBench};
  return table;
}

}  // namespace tidepool::bench
