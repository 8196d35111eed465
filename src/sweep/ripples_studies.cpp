// Studies of the ripples model: dispersion (phase-speed error against cost, per Courant number)
// and stability (noise growth and phase error against the Courant number, with the 1/√2 limit).
#include <cmath>
#include <limits>
#include <numbers>

#include "bench/bench.h"
#include "sim/ripples/measure/ripples_measure.h"
#include "sim/ripples/ripples.h"
#include "sweep/sweep.h"

namespace tidepool::sweep {
namespace {

std::string courantLabel(double c) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "C = %.2f", c);
  return buf;
}

// GPU ms of one wave step on an n x n grid (median of a few).
double msPerStep(gl::ShaderLibrary& shaders, int n, double courant) {
  const ripples::Params p = ripples::periodicWaveGrid(n, n);
  ripples::Ripples model(shaders, p);
  model.touch(0.5f, 0.5f, 0.1f, -0.01f);
  const double dt = courant * p.cellSize / p.waveSpeed;
  constexpr int kSteps = 20;
  const bench::Common timing{"auto", "", 5, 1};
  return bench::gpuMedianMs(timing,
                            [&] {
                              for (int i = 0; i < kSteps; ++i) model.stepOnce(dt);
                            }) /
         kSteps;
}

Result dispersion(Env& env) {
  // The physical problem: waves of length 1 m at c = 1 m/s in an 8 m x 8 m pool. N cells per
  // wavelength means an 8N x 8N grid and dt = C/N s, so a simulated second costs N/C steps.
  Result r = emptyResult("ripples", {"cells_per_wavelength", "courant", "phase_error", "predicted_error"},
                         {.title = "ripples-dispersion: phase-speed error against cost (wave rule, 5-point "
                                   "Laplacian, leapfrog)",
                          .xLabel = "GPU ms per simulated second (8 m pool, 1 m waves)",
                          .yLabel = "phase-speed error |c̃/c - 1|"});
  const std::vector<double> courants =
      env.quick ? std::vector<double>{0.25, 0.5} : std::vector<double>{0.1, 0.25, 0.5, 0.7};
  const std::vector<int> cells = env.quick ? std::vector<int>{8, 16} : std::vector<int>{4, 6, 8, 12, 16, 24, 32};
  for (double c : courants)
    for (int n : cells) {
      const double k = 2 * std::numbers::pi / n;
      const double measured = ripples::measuredPhaseRatio(env.shaders, 2 * n, 8, k, 0.0, c, 3.0);
      const double predicted = ripples::predictedPhaseRatio(k, 0.0, c);
      Row row;
      row.method = courantLabel(c);
      row.dt = c / n;
      row.resolution = std::to_string(n) + " cells/wavelength";
      row.costMsPerSimS = msPerStep(env.shaders, 8 * n, c) * n / c;
      row.metrics = {double(n), c, std::abs(measured - 1.0), std::abs(predicted - 1.0)};
      addCostRow(r, row, std::abs(measured - 1.0));
    }
  return r;
}

Result stability(Env& env) {
  Result r =
      emptyResult("ripples", {"courant", "noise_growth", "phase_error_10_cells"},
                  {.title = "ripples-stability: what the Courant number costs in accuracy, and where it blows up",
                   .xLabel = "Courant number C = c dt / dx",
                   .yLabel = "noise growth after 2000 steps / phase-speed error",
                   .logX = false,
                   .pareto = false,
                   .markerX = 1.0 / std::sqrt(2.0),
                   .markerLabel = "1/√2"});
  std::vector<double> courants;
  for (double c = 0.05; c < 0.86; c += env.quick ? 0.2 : 0.05) courants.push_back(c);
  if (!env.quick)
    for (double c : {0.69, 0.70, 0.705, 0.71, 0.715, 0.72}) courants.push_back(c);
  std::sort(courants.begin(), courants.end());
  const ripples::Params grid = ripples::periodicWaveGrid(32, 32);
  constexpr double kCap = 1e6;  // blow-ups are drawn at this ceiling
  for (double c : courants) {
    const double growth = ripples::noiseGrowth(env.shaders, grid, c * grid.cellSize / grid.waveSpeed, 2000, kCap);
    const bool stable = std::isfinite(growth);
    const double k = 2 * std::numbers::pi / 10;
    const double phaseError = stable ? std::abs(ripples::measuredPhaseRatio(env.shaders, 20, 8, k, 0.0, c, 3.0) - 1.0)
                                     : std::numeric_limits<double>::quiet_NaN();
    Row g;
    g.method = "noise growth after 2000 steps";
    g.dt = c * grid.cellSize / grid.waveSpeed;
    g.resolution = "32x32";
    g.metrics = {c, stable ? growth : std::numeric_limits<double>::infinity(), phaseError};
    g.stable = stable;
    g.x = c;
    g.y = stable ? growth : kCap;
    r.rows.push_back(g);
    announce(g);
    Row p = g;
    p.method = "phase-speed error, 10 cells per wavelength";
    p.y = phaseError;
    r.rows.push_back(p);
  }
  return r;
}

}  // namespace

Study ballsRestitutionStudy();  // balls_studies.cpp
Study ballsSettleStudy();       // balls_settle_study.cpp
Study ballsDambreakStudy();     // balls_dambreak_study.cpp
Study swarmOrbitStudy();        // swarm_studies.cpp
Study swarmPrecisionStudy();
Study lifePrecisionStudy();   // life_studies.cpp
Study swarmStabilityStudy();  // stability_studies.cpp
Study lifeStabilityStudy();
Study ballsStabilityStudy();
Study fluidDensityStudy();  // water_studies.cpp
Study waterFrontStudy();
Study fluidStabilityStudy();  // fluid_stability_study.cpp

const std::vector<Study>& studies() {
  static const std::vector<Study> table = {
      ballsRestitutionStudy(),
      ballsSettleStudy(),
      ballsDambreakStudy(),
      swarmOrbitStudy(),
      swarmPrecisionStudy(),
      lifePrecisionStudy(),
      swarmStabilityStudy(),
      lifeStabilityStudy(),
      ballsStabilityStudy(),
      fluidDensityStudy(),
      waterFrontStudy(),
      fluidStabilityStudy(),
      {"ripples-dispersion", "phase-speed error vs cost per Courant number (wave rule)", dispersion},
      {"ripples-stability", "noise growth and phase error vs Courant number, with the 1/sqrt(2) limit", stability},
  };
  return table;
}

}  // namespace tidepool::sweep
