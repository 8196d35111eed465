// Studies of the balls model: the spring-dashpot restitution against cost, per integrator.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "bench/bench.h"
#include "sim/balls/balls.h"
#include "sim/balls/measure/balls_measure.h"
#include "sweep/sweep.h"
#include "sweep/water_run.h"

namespace tidepool::sweep {
namespace {

// GPU ms of one step of a resting column of about n balls (the cost of a step hardly depends
// on dt, so a simulated second costs this / dt).
double msPerStep(gl::ShaderLibrary& shaders, int n, balls::Integrator integrator) {
  balls::Params p;
  p.fill = water::Fill::Lattice;
  p.latticeCount = n;
  p.latticeScaling = false;
  p.radius = 0.5f / std::cbrt(float(n)) * 0.98f;
  p.integrator = integrator;
  p.dt = 1e-4f;
  balls::Balls model(shaders, p);
  const bench::Common timing{"auto", "", 5, 2};
  constexpr int kSteps = 5;
  return bench::gpuMedianMs(timing,
                            [&] {
                              for (int i = 0; i < kSteps; ++i) model.stepOnce();
                            }) /
         kSteps;
}

}  // namespace

// GPU ms of `steps` steps of a running model, in chunks (GL timer queries; wall clock between
// glFinish calls on a software renderer, as bench::gpuMedianMs does). Used by the studies that
// measure their own runs: the cost is that of the run, contacts and all.
double timedSteps(long steps, const std::function<void()>& step) {
  const bench::Common once{"auto", "", 1, 0};
  constexpr long kChunk = 500;
  double ms = 0;
  for (long done = 0; done < steps; done += kChunk) {
    const long n = std::min(kChunk, steps - done);
    ms += bench::gpuMedianMs(once, [&] {
      for (long i = 0; i < n; ++i) step();
    });
  }
  return ms;
}

double timedSteps(balls::Balls& model, long steps) {
  return timedSteps(steps, [&] { model.stepOnce(); });
}

namespace {

Result restitution(Env& env) {
  constexpr float kE = 0.5f, kContactTime = 0.01f;
  Result r = emptyResult("balls", {"steps_per_contact", "restitution", "restitution_error", "contact_steps"},
                         {.title = "balls-restitution: spring-dashpot restitution error against cost (e = 0.5, t_c "
                                   "= 10 ms)",
                          .xLabel = "GPU ms per simulated second (65k-ball column; t_c/dt from 5 to 100)",
                          .yLabel = "restitution error |e_{measured} / e - 1|"});
  const int columnBalls = env.quick ? 4096 : 65536;
  const std::vector<float> ratios =
      env.quick ? std::vector<float>{10, 50} : std::vector<float>{5, 7, 10, 14, 20, 30, 50, 70, 100};
  for (balls::Integrator integrator :
       {balls::Integrator::ExplicitEuler, balls::Integrator::SymplecticEuler, balls::Integrator::VelocityVerlet}) {
    const double stepMs = msPerStep(env.shaders, columnBalls, integrator);
    for (float ratio : ratios) {
      const balls::Bounce b = balls::measureBounce(env.shaders, integrator, kE, ratio);
      const double dt = kContactTime / ratio;
      Row row;
      row.method = balls::kIntegratorNames[int(integrator)];
      row.dt = dt;
      row.resolution = "t_c/dt = " + std::to_string(int(ratio));
      row.costMsPerSimS = stepMs / dt;
      const double error = b.restitution > 0 ? std::abs(b.restitution / kE - 1.0) : INFINITY;
      row.stable = std::isfinite(error);
      row.metrics = {ratio, b.restitution, error, double(b.contactSteps)};
      addCostRow(r, row, error);
    }
  }
  return r;
}

}  // namespace

Study ballsRestitutionStudy() {
  return {"balls-restitution", "spring-dashpot restitution error vs cost per integrator, t_c/dt 5..100", restitution};
}

}  // namespace tidepool::sweep
