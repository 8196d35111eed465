// The table of benchmarks `tidepool bench` offers. Each benchmark adds one line when it lands.
#include "bench/bench.h"

namespace tidepool::bench {

Benchmark addRipplesBench(CLI::App& bench);
Benchmark addSwarmBench(CLI::App& bench);  // bench/swarm_bench.cpp

const std::vector<Registrar>& registrars() {
  static const std::vector<Registrar> table = {addRipplesBench, addSwarmBench};
  return table;
}

}  // namespace tidepool::bench
