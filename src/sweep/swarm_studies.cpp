// Studies of the swarm: energy error on a circular orbit against cost per integrator (the slopes
// show the orders), and what fp16 state storage costs in accuracy against what it saves.
#include <cmath>

#include "bench/bench.h"
#include "sim/swarm/measure/swarm_measure.h"
#include "sim/swarm/swarm.h"
#include "sweep/sweep.h"

namespace tidepool::sweep {
namespace {

// GPU ms of one step of n particles with the orbit preset (a step's cost does not depend on dt).
double msPerStep(gl::ShaderLibrary& shaders, int n, sim::Integrator integrator, sim::Storage storage) {
  sim::SwarmParams p;
  p.particles = n;
  p.integrator = integrator;
  p.storage = storage;
  sim::Swarm swarm(shaders, p);
  const bench::Common timing{"auto", "", 5, 2};
  return bench::gpuMedianMs(timing, [&] { swarm.step(1.0 / 120.0); });
}

// One curve: a row per steps-per-orbit, the cost of one step of n particles timed once.
void addOrbitCurve(Env& env, Result& r, int n, sim::Integrator integrator, sim::Storage storage,
                   const std::vector<int>& stepsPerOrbit, const std::string& method) {
  const double stepMs = msPerStep(env.shaders, n, integrator, storage);
  for (int steps : stepsPerOrbit) {
    const double error = sim::orbitEnergyError(env.shaders, integrator, storage, steps);
    Row row;
    row.method = method;
    row.dt = sim::orbitPeriod() / steps;
    row.resolution = std::to_string(steps) + " steps/orbit";
    row.costMsPerSimS = stepMs / row.dt;
    row.stable = std::isfinite(error);
    row.metrics = {double(steps), error};
    addCostRow(r, row, error);
  }
}

// Both studies chart the orbit's energy error against the cost of 1M particles (16k when quick).
Result orbitFrame(const std::string& title) {
  return emptyResult("swarm", {"steps_per_orbit", "energy_error"},
                     {.title = title,
                      .xLabel = "GPU ms per simulated second (1M particles)",
                      .yLabel = "max |{/Symbol D}E| / s over 10 orbits"});
}

Result orbit(Env& env) {
  Result r = orbitFrame("swarm-orbit: energy error after 10 orbits against cost, per integrator (fp32)");
  const int n = env.quick ? 1 << 14 : 1 << 20;
  const std::vector<int> steps = env.quick ? std::vector<int>{50, 200} : std::vector<int>{25, 50, 100, 200, 400, 800};
  for (sim::Integrator integrator : {sim::Integrator::ExplicitEuler, sim::Integrator::SymplecticEuler,
                                     sim::Integrator::Verlet, sim::Integrator::Rk4})
    addOrbitCurve(env, r, n, integrator, sim::Storage::Fp32, steps, sim::kIntegratorNames[int(integrator)]);
  return r;
}

Result precision(Env& env) {
  Result r = orbitFrame("swarm-precision: fp16 against fp32 state (velocity Verlet and RK4 on the orbit)");
  const int n = env.quick ? 1 << 14 : 1 << 20;
  const std::vector<int> steps = env.quick ? std::vector<int>{100} : std::vector<int>{50, 100, 200, 400};
  for (sim::Integrator integrator : {sim::Integrator::Verlet, sim::Integrator::Rk4})
    for (sim::Storage storage : {sim::Storage::Fp32, sim::Storage::Fp16})
      addOrbitCurve(env, r, n, integrator, storage, steps,
                    std::string(sim::kIntegratorNames[int(integrator)]) + " " + sim::kStorageNames[int(storage)]);
  return r;
}

}  // namespace

Study swarmOrbitStudy() { return {"swarm-orbit", "energy error on a circular orbit vs cost, per integrator", orbit}; }
Study swarmPrecisionStudy() { return {"swarm-precision", "fp16 vs fp32 state: energy error vs cost", precision}; }

}  // namespace tidepool::sweep
