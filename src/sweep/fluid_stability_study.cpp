// fluid-stability: the largest time step at which position-based fluid runs 0.5 s of a scene
// without the divergence watch firing (a NaN, a particle outside the walls, or one moving more
// than h per step: Fluid::speedBound()), bisected for 1, 2, 4 and 8 solver iterations on the dam
// break (dam-break-fluid.json, d = 0.02 m) and the resting tank (fluid-tank.json), beside what
// theory says. A run is also sampled every 20 ms (the same three checks, blocking), so a speed
// spike between two of the watch's checks is not missed.
//
// Theory (docs/WATER.md, "Water: balls and fluid on one metric"):
//  - Similarity. With no damping, a PBF step in positions is x' = 2x − x_prev + g·dt² then the
//    iterations (positions only; XSPH blends a fixed fraction per step), and the watch asks
//    |x' − x| < h: dt enters only through g·dt² (and the steps a run of 0.5 s takes). So for a
//    scene and k, failure is near a fixed G = g·dt²/d, and the limit in dt is a square root.
//  - Neighbours (CFL). A particle moving faster than h/dt skips neighbours; the fastest water of
//    a dam break is its front, 2·sqrt(g·H) in shallow-water theory (Ritter 1892; free fall from
//    the top would give only sqrt(2·g·H)). Hence dt ≤ h / (2·sqrt(g·H)), whatever k.
//  - Compression. In a resting column each step's k Jacobi iterations must return every particle
//    by the g·dt² that the prediction moved it. For a slowly varying compression C(z), an
//    iteration moves a particle by Σ_j V0 (λ_i + λ_j) ∇W_ij ≈ ∇λ (Σ_j V0 ∇W_ij = 0 and
//    Σ_j V0 (x_j − x_i) ⊗ ∇W_ij = I in the bulk), with λ = −C / ((1 + ε)·S), S = Σ_j |V0 ∇W|² of
//    the rest lattice and ε the relaxation. Hence k·|C'|/((1 + ε)·S) = g·dt²: the floor of a
//    column of depth H holds C_floor = (1 + ε)·S·g·dt²·H / k. If the fluid fails at a fixed
//    floor compression C*, the limit is dt = sqrt(C*·k / ((1 + ε)·S·g·H)): it grows as √k and
//    falls as 1/√H. C* is not derived: the chart draws this law through the tank's measured
//    limit at 4 iterations (the scenes' setting), so every other point is a prediction.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "scene/fluid_stage.h"
#include "scene/scene.h"
#include "sim/balls/measure/balls_measure.h"
#include "sim/fluid/rest_lattice.h"
#include "sim/measure/bisect.h"
#include "sweep/sweep.h"
#include "sweep/water_run.h"

namespace tidepool::sweep {
namespace {

constexpr double kSampleEvery = 0.02;  // s

struct Trial {
  bool stable = true;
  double largestMove = 0;     // largest speed × dt / h over the samples (the watch fails at 1)
  double maxSpeed = 0;        // m/s
  double maxCompression = 0;  // largest ρ/ρ0 − 1 over the samples
  double costMsPerSimS = 0;
};

Trial trial(gl::ShaderLibrary& shaders, fluid::Params p, double dt, double duration) {
  p.dt = float(dt);
  WaterRun run(shaders, p);
  Trial t;
  for (int j = 1; j * kSampleEvery <= duration + 1e-9 && t.stable; ++j) {
    run.advanceTo(j * kSampleEvery, true);
    const WaterSample s = run.sample();
    t.largestMove = std::max(t.largestMove, s.maxSpeed / run.speedBound());
    t.maxSpeed = std::max(t.maxSpeed, s.maxSpeed);
    t.maxCompression = std::max(t.maxCompression, s.compressionMax);
    t.stable = s.healthy && !run.divergence();
  }
  t.costMsPerSimS = run.gpuMs() / run.time();
  return t;
}

struct Setup {
  const char* name;  // the curve: "tank", "dam break"
  const char* file;  // assets/scenes
  fluid::Params params;
  double depth = 0;      // H, m: the water's height (the slab, the column)
  double gradients = 0;  // S of the rest lattice, 1/m²
};

Setup setup(const char* name, const char* file) {
  Setup s{name, file, fluidScene(loadScene(resolveScenePath(file))).model};
  const water::Setup& w = s.params;
  s.depth = w.fill == water::Fill::Slab ? double(w.slabHeight) : balls::columnScales(w).height;
  s.gradients = fluid::restLattice(s.params.spacing(), s.params.h(), fluid::Packing::Cubic).gradients;
  return s;
}

// (1 + ε)·S·g·H: the floor compression is this × dt² / k.
double compressionPerStep(const Setup& s) {
  return (1.0 + double(s.params.relaxation)) * s.gradients * std::abs(double(s.params.gravity.z)) * s.depth;
}

Row limitRow(const std::string& method, const Setup& s, int k, double dt, double cost, double speed) {
  Row row;
  row.method = method;
  row.dt = dt;
  char resolution[64];
  std::snprintf(resolution, sizeof resolution, "%s, d = %.3g m", s.name, double(s.params.spacing()));
  row.resolution = resolution;
  row.stable = dt > 0;  // 0: unstable at the smallest dt tried
  row.costMsPerSimS = cost;
  row.metrics = {double(k), compressionPerStep(s) * dt * dt / k, speed};
  row.x = k;
  row.y = 1e3 * dt;
  return row;
}

Result stability(Env& env) {
  const double duration = env.quick ? 0.3 : 0.5;
  const double smallest = env.quick ? 0.002 : 0.001, largest = env.quick ? 0.064 : 0.128;
  const double tolerance = env.quick ? 0.1 : 0.02;
  const std::vector<int> iterations = env.quick ? std::vector<int>{1, 4} : std::vector<int>{1, 2, 4, 8};
  std::vector<Setup> scenes = {setup("tank", "fluid-tank")};
  if (!env.quick) scenes.push_back(setup("dam break", "dam-break-fluid"));

  char label[96];
  std::snprintf(label, sizeof label, "largest stable dt, ms (%.2g s without the divergence watch firing)", duration);
  Result r = emptyResult("fluid", {"iterations", "floor_compression", "max_speed"},
                         {.title = "fluid-stability: the largest stable dt of position-based fluid against its "
                                   "iterations, beside theory",
                          .xLabel = "solver iterations per step",
                          .yLabel = label,
                          .pareto = false});
  double anchor = 0;  // C*: the tank's floor compression at its measured limit with 4 iterations
  std::vector<Row> measured;
  for (const Setup& s : scenes) {
    std::printf("  %s: H = %.3g m, S = %.4g /m^2, N = %zu\n", s.name, s.depth, s.gradients,
                WaterRun(env.shaders, s.params).count());
    for (int k : iterations) {
      fluid::Params p = s.params;
      p.iterations = k;
      Trial best;
      double bestDt = 0;
      auto isStable = [&](double dt) {
        const Trial t = trial(env.shaders, p, dt, duration);
        std::printf("    %d iterations, dt = %.4g ms: largest move %.3g h, max compression %.3g: %s\n", k, 1e3 * dt,
                    t.largestMove, t.maxCompression, t.stable ? "stable" : "UNSTABLE");
        std::fflush(stdout);
        if (t.stable && dt > bestDt) {
          best = t;
          bestDt = dt;
        }
        return t.stable;
      };
      double limit = largestStable(smallest, largest, tolerance, isStable);
      if (limit > 0 && isStable(largest)) limit = largest;  // never failed in the range: a lower bound
      const Row row = limitRow(std::string(s.name) + ": measured", s, k, limit, best.costMsPerSimS, best.maxSpeed);
      std::printf("  %s, %d iterations: largest stable dt %.4g ms (floor compression there %.3g, speed %.3g m/s)\n",
                  s.name, k, 1e3 * limit, row.metrics[1], best.maxSpeed);
      measured.push_back(row);
      if (std::string(s.name) == "tank" && k == 4) anchor = row.metrics[1];
    }
  }
  for (const Row& row : measured) r.rows.push_back(row);
  // The theories: the front's CFL bound (the dam break), the floor compression C* (both scenes).
  for (const Setup& s : scenes) {
    const double g = std::abs(double(s.params.gravity.z)), front = 2.0 * std::sqrt(g * s.depth);
    const bool flows = std::string(s.name) == "dam break";
    if (flows)
      std::printf("  %s: theory: CFL of the front 2 sqrt(gH): dt <= %.4g ms\n", s.name, 1e3 * s.params.h() / front);
    for (int k : iterations) {
      if (flows)
        r.rows.push_back(
            limitRow(std::string(s.name) + ": theory, front CFL h / 2 sqrt(gH)", s, k, s.params.h() / front, 0, front));
      if (anchor <= 0) continue;
      const double dt = std::sqrt(anchor * k / compressionPerStep(s));
      std::printf("  %s, %d iterations: theory: floor compression %.3g (the tank's at 4 iterations) at dt = %.4g ms\n",
                  s.name, k, anchor, 1e3 * dt);
      r.rows.push_back(limitRow(std::string(s.name) + ": theory, floor compression of the tank at k = 4", s, k, dt, 0,
                                std::numeric_limits<double>::quiet_NaN()));
    }
  }
  return r;
}

}  // namespace

Study fluidStabilityStudy() {
  return {"fluid-stability", "largest stable dt of the fluid vs its iterations (dam break, tank), beside theory",
          stability};
}

}  // namespace tidepool::sweep
