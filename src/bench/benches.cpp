// The table of benchmarks `tidepool bench` offers. Each benchmark adds one line when it lands.
#include "bench/bench.h"

namespace tidepool::bench {

Benchmark addBallsBench(CLI::App& bench);    // balls_bench.cpp
Benchmark addExportBench(CLI::App& bench);   // export_bench.cpp
Benchmark addFluidBench(CLI::App& bench);    // fluid_bench.cpp
Benchmark addGridBench(CLI::App& bench);     // grid_bench.cpp
Benchmark addMemoryBench(CLI::App& bench);   // memory_bench.cpp
Benchmark addRenderBench(CLI::App& bench);   // render_bench.cpp
Benchmark addRipplesBench(CLI::App& bench);  // ripples_bench.cpp
Benchmark addSurfaceBench(CLI::App& bench);  // surface_bench.cpp
Benchmark addLifeBench(CLI::App& bench);     // life_bench.cpp
Benchmark addSwarmBench(CLI::App& bench);    // swarm_bench.cpp

const std::vector<Registrar>& registrars() {
  static const std::vector<Registrar> table = {addBallsBench,   addExportBench, addFluidBench,  addGridBench,
                                               addLifeBench,    addMemoryBench, addRenderBench, addRipplesBench,
                                               addSurfaceBench, addSwarmBench};
  return table;
}

}  // namespace tidepool::bench
