// balls-dambreak: the dam-break scene (assets/scenes/dam-break.json: a column a wide and 2a high
// against the back wall, spring-dashpot contacts) run to T* = t·sqrt(g/a) = 2.5 at several dt.
// The surge front (balls_measure frontOverWidth, the `validate --probe front` quantity, in units
// of a) is sampled at T* = 0.1, 0.2, ... 2.5, interpolated linearly between the two steps around
// each sample time; each run's error is the RMS deviation of that curve from a reference run of
// the scene's own method at the finest dt, from the same initial state and with the same N.
// The reference method is also run again at the finest dt: that row's deviation is the run-to-run
// spread (GPU atomics order the fp32 sums differently in each run, and the splash is chaotic), the
// floor below which no dt can go. The contact time scales with r, which keeps the scene's relative
// overlaps: --quick runs r = 1.6 cm (about 1k balls), the default r = 4 mm (about 75k).
#include <cmath>
#include <cstdio>
#include <limits>

#include "base/error.h"
#include "scene/balls_stage.h"
#include "scene/scene.h"
#include "sim/balls/balls.h"
#include "sim/balls/measure/balls_measure.h"
#include "sweep/sweep.h"

namespace tidepool::sweep {

double timedSteps(balls::Balls& model, long steps);  // balls_studies.cpp

namespace {

constexpr double kEndTime = 2.5, kSampleEvery = 0.1, kEarlyEnd = 1.2;  // T*

struct Curve {
  std::vector<double> front;  // front / a at each sample time (NaN after a blow-up)
  double maxOverlap = 0;      // over the samples, fraction of r
  double ms = 0, simulated = 0;
  std::size_t count = 0;  // balls
  bool stable = true;
};

Curve runFront(gl::ShaderLibrary& shaders, const balls::Params& p, const std::vector<double>& times) {
  balls::Balls model(shaders, p);
  Curve c;
  c.count = model.count();
  const double dt = p.dt;
  auto sample = [&] {
    const balls::Stats s = model.stats();
    c.maxOverlap = std::max(c.maxOverlap, s.maxOverlap);
    if (s.nonFinite > 0 || s.outside > 0 || s.maxOverlap > 1.0) c.stable = false;
    return balls::frontOverWidth(p, s, model.radius());
  };
  for (double t : times) {
    if (!c.stable) {
      c.front.push_back(std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    const long before = std::max(0L, long(std::floor((t - model.time()) / dt + 1e-9)));
    c.ms += timedSteps(model, before);
    const double t0 = model.time(), f0 = sample();
    if (t0 >= t - 1e-12 * t || !c.stable) {
      c.front.push_back(c.stable ? f0 : std::numeric_limits<double>::quiet_NaN());
      continue;
    }
    c.ms += timedSteps(model, 1);
    const double t1 = model.time(), f1 = sample();
    c.front.push_back(c.stable ? f0 + (f1 - f0) * (t - t0) / (t1 - t0) : std::numeric_limits<double>::quiet_NaN());
  }
  c.simulated = model.time();
  return c;
}

struct Method {
  std::string name;
  balls::Integrator integrator;
  std::vector<int> stepsPerContact;  // t_c / dt
};

Result dambreak(Env& env) {
  balls::Params scene = ballsParams(loadScene(resolveScenePath("dam-break")));
  const float radius = env.quick ? 0.016f : 0.004f;
  scene.contactTime *= radius / scene.radius;
  scene.radius = radius;
  scene.substeps = 1;
  const double a = balls::columnScales(scene).width;
  const double g = std::abs(double(scene.gravity.z));
  std::vector<double> times;  // s
  for (int k = 1; k * kSampleEvery <= kEndTime + 1e-9; ++k) times.push_back(k * kSampleEvery / std::sqrt(g / a));
  const int early = int(std::lround(kEarlyEnd / kSampleEvery));

  using I = balls::Integrator;
  const int finest = env.quick ? 40 : 80;
  const std::string reference = balls::kIntegratorNames[int(scene.integrator)];
  std::vector<Method> methods;
  if (env.quick)
    methods = {{reference, scene.integrator, {5, 10, 20}}, {"verlet", I::VelocityVerlet, {5, 10, 20}}};
  else
    methods = {{reference, scene.integrator, {3, 5, 10, 20, 40}},
               {"verlet", I::VelocityVerlet, {3, 5, 10, 20, 40, finest}},
               {"explicit-euler", I::ExplicitEuler, {5, 10, 20, 40, finest}}};
  methods.push_back({"reference rerun (run-to-run spread)", scene.integrator, {finest}});

  auto withStep = [&](I integrator, int perContact) {
    balls::Params p = scene;
    p.integrator = integrator;
    p.dt = scene.contactTime / float(perContact);
    return p;
  };
  const Curve ref = runFront(env.shaders, withStep(scene.integrator, finest), times);
  if (!ref.stable)
    throw Error("balls-dambreak: the reference run (" + reference + ", t_c/dt = " + std::to_string(finest) +
                ") is not stable");

  Result r = emptyResult(
      "balls", {"steps_per_contact", "rms_deviation", "max_deviation", "rms_deviation_early", "max_overlap_r"});
  for (const Method& m : methods)
    for (int perContact : m.stepsPerContact) {
      const balls::Params p = withStep(m.integrator, perContact);
      const Curve c = runFront(env.shaders, p, times);
      double sum = 0, sumEarly = 0, worst = 0;
      for (std::size_t i = 0; i < times.size(); ++i) {
        const double d = c.front[i] - ref.front[i];
        sum += d * d;
        if (int(i) < early) sumEarly += d * d;
        worst = std::max(worst, std::abs(d));
      }
      const double nan = std::numeric_limits<double>::quiet_NaN();
      const double rms = c.stable ? std::sqrt(sum / times.size()) : nan;
      Row row;
      row.method = m.name;
      row.dt = p.dt;
      row.resolution = "t_c/dt = " + std::to_string(perContact);
      row.costMsPerSimS = c.ms / c.simulated;
      row.stable = c.stable && std::isfinite(rms);
      row.metrics = {double(perContact), rms, c.stable ? worst : nan, c.stable ? std::sqrt(sumEarly / early) : nan,
                     c.maxOverlap};
      addCostRow(r, row, rms);
      std::printf("  %-18s t_c/dt = %3d: RMS front deviation %.3g a (to T* = 1.2: %.3g a), %s\n", m.name.c_str(),
                  perContact, rms, row.metrics[3], row.stable ? "stable" : "UNSTABLE");
      std::fflush(stdout);
    }
  char label[160];
  std::snprintf(label, sizeof label, "GPU ms per simulated second (dam break, N = %zu, r = %.3g m, t_c = %.3g ms)",
                ref.count, double(radius), 1e3 * double(scene.contactTime));
  r.chart.title = "balls-dambreak: surge-front deviation from the finest-dt run against cost (to T* = 2.5)";
  r.chart.xLabel = label;
  r.chart.yLabel = "RMS deviation of the front x/a";
  return r;
}

}  // namespace

Study ballsDambreakStudy() {
  return {"balls-dambreak", "surge-front deviation from a finest-dt reference vs cost, per integrator", dambreak};
}

}  // namespace tidepool::sweep
