// The water studies: both water models, balls (DEM, spring-dashpot contacts) and fluid
// (position-based fluid), on the same water and the same metrics (water_run.h).
//
// fluid-density: the resting tank (fluid-tank.json: 0.2 m of water, d = 0.02 m). The fluid at
//   1–12 iterations × dt 1, 2, 4 ms; the balls (r = d·2^(1/6)/2 as asBalls, a slab on the HCP lattice, t_c = 20 dt,
//   e = 0.5) at dt 0.1, 0.2, 0.4 ms. Each settles 0.4 s; then the density error (mean over the
//   particles of max(ρ/ρ0 − 1, 0), read with the fluid's kernel for both models) is averaged over
//   five samples in the next 0.1 s, and its max kept. The full run widens the tank to 1.6 × 1.6 m
//   (64,000 fluid particles, 87,051 balls) so that the cost is a GPU-sized one; depth and spacing stay.
//   Theory for the fluid (fluid_stability_study.cpp): a resting column's floor compression is
//   (1 + ε)·S·g·dt²·H/k, so the mean over the column is about half that, falling as dt²/k.
// water-front: the dam break (dam-break.json for the balls, dam-break-fluid.json for the fluid:
//   the same column a = 0.25 m wide, 0.5 m high, in a 1 m tank) at d = 0.04, 0.02, 0.01 m, with dt
//   proportional to d (fluid 0.05 s/m × d, 4 iterations; balls 0.01 s/m × d, t_c = 20 dt), which
//   keeps both the Courant number and the relative compression of each model. The surge front
//   (front + r − domain min x)/a is sampled every 4 ms to t = 0.3 s; a run's error is the RMS
//   difference of its curve from the finest run of the same model, and front_vs_other_model the
//   RMS difference between the balls' and the fluid's curves at the same d. Each run's RMS
//   distance from Martin & Moyce's measured front is printed.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "scene/balls_stage.h"
#include "scene/fluid_stage.h"
#include "scene/scene.h"
#include "scene/water_stage.h"
#include "sim/balls/measure/balls_measure.h"
#include "sim/fluid/rest_lattice.h"
#include "sweep/sweep.h"
#include "sweep/water_run.h"

namespace tidepool::sweep {
namespace {

const std::string kBallsMethod = "spring-dashpot tc = 20 dt, symplectic-euler";  // as balls-settle writes it
constexpr float kStepsPerContact = 20.0f;

std::string fluidMethod(int iterations) { return "pbf, " + std::to_string(iterations) + " iterations"; }

// The balls with spring-dashpot contacts of t_c = 20 dt (e = 0.5), symplectic Euler.
balls::Params ballsOn(const balls::Params& water, double dt) {
  balls::Params p = water;
  p.contact = balls::Contact::SpringDashpot;
  p.integrator = balls::Integrator::SymplecticEuler;
  p.dt = float(dt);
  p.contactTime = kStepsPerContact * float(dt);
  p.restitution = 0.5f;
  return p;
}

// --- fluid-density ------------------------------------------------------------------------------

constexpr double kSettle = 0.4, kWindow = 0.1;  // s
constexpr int kDensitySamples = 5;

struct Density {
  double mean = 0, max = -INFINITY, cost = 0;
  bool stable = true;
  std::size_t count = 0;
};

template <class Params>
Density restingDensity(gl::ShaderLibrary& shaders, const Params& params) {
  WaterRun run(shaders, params);
  Density d;
  d.count = run.count();
  run.advanceTo(kSettle);
  for (int j = 1; j <= kDensitySamples; ++j) {
    run.advanceTo(kSettle + kWindow * j / kDensitySamples);
    const WaterSample s = run.sample();
    d.mean += s.compressionMean / kDensitySamples;
    d.max = std::max(d.max, s.compressionMax);
    d.stable = d.stable && s.healthy;
  }
  d.cost = run.gpuMs() / run.time();
  return d;
}

Row densityRow(const std::string& model, const std::string& method, double dt, const Density& d, int iterations,
               double depth, double spacing) {
  Row row;
  row.model = model;
  row.method = method;
  row.dt = dt;
  char resolution[96];
  std::snprintf(resolution, sizeof resolution, "N = %zu, d = %.3g m, %.3g m deep", d.count, spacing, depth);
  row.resolution = resolution;
  row.costMsPerSimS = d.cost;
  row.stable = d.stable && std::isfinite(d.mean);
  row.metrics = {d.mean, d.max, double(iterations)};
  return row;
}

Result fluidDensity(Env& env) {
  fluid::Params tank = fluidScene(loadScene(resolveScenePath("fluid-tank"))).model;
  if (!env.quick) tank.domainMax.x = tank.domainMax.y = 1.6f;  // 64k particles, same depth
  const double depth = tank.slabHeight, g = std::abs(double(tank.gravity.z));
  const double gradients = fluid::restLattice(tank.spacing(), tank.h(), fluid::Packing::Cubic).gradients;
  const std::vector<int> iterations = env.quick ? std::vector<int>{1, 4} : std::vector<int>{1, 2, 3, 4, 6, 8, 12};
  const std::vector<double> fluidDts = env.quick ? std::vector<double>{2e-3} : std::vector<double>{1e-3, 2e-3, 4e-3};
  const std::vector<double> ballsDts =
      env.quick ? std::vector<double>{2e-4, 4e-4} : std::vector<double>{1e-4, 2e-4, 4e-4};

  Result r = emptyResult("water", {"density_error_mean", "density_error_max", "iterations"});
  for (int k : iterations)
    for (double dt : fluidDts) {
      fluid::Params p = tank;
      p.iterations = k;
      p.dt = float(dt);
      const Density d = restingDensity(env.shaders, p);
      const double theory = 0.5 * (1.0 + double(p.relaxation)) * gradients * g * dt * dt * depth / k;
      addCostRow(r, densityRow("fluid", fluidMethod(k), dt, d, k, depth, tank.spacing()), d.mean);
      std::printf(
          "  fluid, %2d iterations, dt = %.3g ms: density error mean %.3g (half the hydrostatic floor "
          "compression: %.3g), max %.3g, %.3g GPU ms per s, %s\n",
          k, 1e3 * dt, d.mean, theory, d.max, d.cost, d.stable ? "stable" : "UNSTABLE");
      std::fflush(stdout);
    }
  for (double dt : ballsDts) {
    // The same water as balls (asBalls: the radius of equal particles per volume), as model auto runs it.
    balls::Params own;
    static_cast<water::Setup&>(own) = tank;  // the fluid's step, damping and foam too
    const Density d = restingDensity(env.shaders, ballsOn(asBalls(tank, own), dt));
    addCostRow(r, densityRow("balls", kBallsMethod, dt, d, 0, depth, tank.spacing()), d.mean);
    std::printf("  balls, dt = %.3g ms (t_c = %.3g ms): density error mean %.3g, max %.3g, %.3g GPU ms per s, %s\n",
                1e3 * dt, 1e3 * kStepsPerContact * dt, d.mean, d.max, d.cost, d.stable ? "stable" : "UNSTABLE");
    std::fflush(stdout);
  }
  r.chart.title = "fluid-density: density error of a resting tank against cost, fluid (per iterations) and balls";
  char label[160];
  std::snprintf(label, sizeof label, "GPU ms per simulated second (tank %.3g x %.3g m, %.3g m deep, d = 2r = %.3g m)",
                double(tank.domainMax.x - tank.domainMin.x), double(tank.domainMax.y - tank.domainMin.y), depth,
                double(tank.spacing()));
  r.chart.xLabel = label;
  r.chart.yLabel = "mean density error, mean of max(rho/rho_0 - 1, 0)";
  return r;
}

// --- water-front ---------------------------------------------------------------------------------

constexpr double kFrontEvery = 0.004;  // s: a whole number of steps of every run below

struct Front {
  std::vector<double> front;  // / a at kFrontEvery, 2 kFrontEvery, ... (NaN after a failure)
  double cost = 0;
  std::size_t count = 0;
  bool stable = true;
};

template <class Params>
Front frontCurve(gl::ShaderLibrary& shaders, const Params& params, double end) {
  WaterRun run(shaders, params);
  Front f;
  f.count = run.count();
  for (int j = 1; j * kFrontEvery <= end + 1e-9; ++j) {
    run.advanceTo(j * kFrontEvery);
    const WaterSample s = run.sample(false);
    f.stable = f.stable && s.healthy && std::isfinite(s.front);
    f.front.push_back(f.stable ? s.front : std::numeric_limits<double>::quiet_NaN());
  }
  f.cost = run.gpuMs() / run.time();
  return f;
}

double rmsDifference(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum / double(a.size()));  // NaN when either failed
}

Result waterFront(Env& env) {
  const fluid::Params fluidBase = fluidScene(loadScene(resolveScenePath("dam-break-fluid"))).model;
  const balls::Params ballsBase = ballsParams(loadScene(resolveScenePath("dam-break")));
  const std::vector<float> spacings =
      env.quick ? std::vector<float>{0.04f, 0.02f} : std::vector<float>{0.04f, 0.02f, 0.01f};
  const double end = env.quick ? 0.1 : 0.3;
  const double a = balls::columnScales(ballsBase).width, g = std::abs(double(ballsBase.gravity.z));

  struct Run {
    std::string model, method;
    float spacing;
    double dt;
    Front front;
  };
  std::vector<Run> runs;
  for (float d : spacings) {
    fluid::Params f = fluidBase;
    f.setSpacing(d);
    f.dt = 0.05f * d;  // 1 ms at d = 0.02 m, as the scene
    runs.push_back({"fluid", fluidMethod(f.iterations), d, f.dt, frontCurve(env.shaders, f, end)});
    balls::Params b = ballsOn(ballsBase, 0.01 * d);  // 0.2 ms at r = 0.01 m, t_c = 4 ms: as the scene
    b.radius = asBalls(f, b).radius;                 // the same water volume as the fluid's, as model auto runs it
    runs.push_back({"balls", kBallsMethod, d, b.dt, frontCurve(env.shaders, b, end)});
  }
  auto find = [&](const std::string& model, float d) -> const Run& {
    for (const Run& run : runs)
      if (run.model == model && run.spacing == d) return run;
    throw Error("water-front: no " + model + " run at d = " + std::to_string(d));
  };

  Result r = emptyResult("water", {"front_error", "front_vs_other_model", "iterations"});
  for (const Run& run : runs) {
    const Run& finest = find(run.model, spacings.back());
    const Run& other = find(run.model == "balls" ? "fluid" : "balls", run.spacing);
    const double error = rmsDifference(run.front.front, finest.front.front);
    const double between = rmsDifference(run.front.front, other.front.front);
    int points = 0;
    const double measured = rmsFromMartinMoyce(run.front.front, kFrontEvery, a, g, points);
    Row row;
    row.model = run.model;
    row.method = run.method;
    row.dt = run.dt;
    char resolution[64];
    std::snprintf(resolution, sizeof resolution, "d = %.3g m, N = %zu", double(run.spacing), run.front.count);
    row.resolution = resolution;
    row.costMsPerSimS = run.front.cost;
    row.stable = run.front.stable && std::isfinite(error);
    row.metrics = {error, between, run.model == "fluid" ? double(fluidBase.iterations) : 0.0};
    addCostRow(r, row, error);
    std::printf(
        "  %s, d = %.3g m (N = %zu): front at t = %.3g s %.3g a; RMS from the finest %.3g a, from the %s "
        "%.3g a, from Martin & Moyce %.3g a (%d points); %.3g GPU ms per s, %s\n",
        run.model.c_str(), double(run.spacing), run.front.count, end, run.front.front.back(), error,
        other.model.c_str(), between, measured, points, run.front.cost, row.stable ? "stable" : "UNSTABLE");
    std::fflush(stdout);
  }
  char label[160];
  std::snprintf(label, sizeof label, "GPU ms per simulated second (dam break a = %.3g m, to t = %.3g s)", a, end);
  r.chart = {.title =
                 "water-front: the dam-break surge front's RMS difference from the finest run of its model, "
                 "against cost",
             .xLabel = label,
             .yLabel = "RMS difference of the front x/a from the finest d"};
  return r;
}

}  // namespace

Study waterFrontStudy() {
  return {"water-front", "dam-break front vs resolution and cost, balls and fluid, against the finest of each",
          waterFront};
}

Study fluidDensityStudy() {
  return {"fluid-density", "density error of a resting tank vs cost: fluid per iterations and dt, balls per dt",
          fluidDensity};
}

}  // namespace tidepool::sweep
